// HighLevelPlanningImpl: the HighLevelPlanning.idl servant: check and convert in, service call,
// convert out.
#pragma once

#include "HighLevelPlanning.hh"
#include "servers/common/ServiceServant.h"
#include "servers/highlevelplanning/HighLevelPlanningService.h"

namespace rgnav {

class HighLevelPlanningImpl : public ServiceServant<POA_RGNav::HighLevelPlanning> {
 public:
  HighLevelPlanningImpl(ServerRuntime& runtime, HighLevelPlanningService& service);

  RGNav::TaskInfo* goTo(RGNav::RequestId request, const RGNav::PlanGoal& goal) override;
  RGNav::TaskInfo* explore(RGNav::RequestId request) override;
  RGNav::TaskInfo* stop(RGNav::RequestId request) override;
  RGNav::TaskInfo* cancel(RGNav::RequestId request, RGNav::TaskId id) override;
  RGNav::TaskInfo* task(RGNav::TaskId id) override;
  RGNav::TaskInfoSeq* tasks() override;
  RGNav::NamingQuestionSeq* questions() override;
  void answer(RGNav::RequestId request, RGNav::QuestionId question, const char* name) override;

 private:
  HighLevelPlanningService& service_;
};

}  // namespace rgnav
