// rgnav-eval-crowd: the crowd evaluation of issue 27 ("rgctl eval crowd"): the simulator in real
// time on the office world with walking people, the Low-Level Drive, the Collision Avoidance with
// the ground-truth pose, and the PathPlanning module on an RG map of the office (made once in
// process, OfficeRgMap.h); seeded goals in the rooms, each sent by driveTo and judged by the true
// pose (CrowdRun.h). Last line:
//   crowd: goals=… reached=… robot_collisions=… person_bumps=… mean_speed_mps=…
// With --picture FILE.png it also draws the run (CrowdPicture.h): where the robot drove, where it
// failed. Exit code 0 when the run completed (the figures are judged by their floors, e.g. in CTest).
#include <iostream>

#include "tests/eval/crowd/CrowdEvaluation.h"
#include "tests/eval/crowd/CrowdPicture.h"
#include "tests/support/cluster/Interruption.h"
#include "tools/common/CommandLine.h"

namespace po = boost::program_options;
using namespace rgnav;

int main(int argc, char** argv) {
  CrowdEvaluationOptions options;
  po::options_description description("rgnav-eval-crowd [options]");
  std::string picture;
  description.add_options()("help", "this text")
      ("picture", po::value(&picture), "write a PNG of the run: the driven paths, the goals, the failures");
  options.addTo(description);
  try {
    if (!parseCommandLine(argc, argv, description)) return 0;
    testing::catchInterruptions();
    const PreparedCrowd prepared = prepareCrowd(options);
    CrowdSet set(crowdSetOptions(options, prepared), &prepared.map);
    set.start();
    const CrowdOutcome outcome = driveGoals(set.cluster().clientSettings(), prepared.goals, options.run);
    std::cout << crowdLine(outcome, simulatorCounters(set.cluster().clientSettings())) << std::endl;
    if (!picture.empty()) writeCrowdPicture(picture, prepared.world.grid, prepared.start, outcome);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-eval-crowd: " << e.what() << std::endl;
    return 1;
  }
}
