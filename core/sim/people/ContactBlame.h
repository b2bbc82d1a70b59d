// ContactBlame: whose motion made a contact between the robot and a person, so that the simulator
// counts a collision the robot drove into apart from a person walking into the robot (issue 27's
// crowd rules). The robot drove into the person when the point of its outline nearest the person
// moves towards the person (the robot's translation plus its rotation at that point: a round
// robot turning on the spot drives into nobody, a rectangle's swinging corner does); otherwise
// (standing, driving away, passing sideways) the person walked into the robot.
#pragma once

#include "core/common/Pose2D.h"
#include "core/nav/grid/Footprint.h"

namespace rgnav {

// Towards the person faster than this (m/s) is driving into it.
constexpr double kContactApproachSpeed = 0.01;

// The robot (`footprint` at `robot`, speeds `velocity` m/s forward and `rotational` rad/s) and a
// person whose centre is at `person`.
bool robotDroveInto(const Footprint& footprint, const Pose2D& robot, double velocity, double rotational,
                    const WorldPoint& person);

}  // namespace rgnav
