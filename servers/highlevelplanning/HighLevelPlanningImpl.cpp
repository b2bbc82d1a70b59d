// The HighLevelPlanning.idl servant (see HighLevelPlanningImpl.h).
#include "servers/highlevelplanning/HighLevelPlanningImpl.h"

#include "clientlibs/common/convert.h"
#include "clientlibs/highlevelplanning/convert.h"
#include "clientlibs/pathplanning/convert.h"
#include "servers/common/WireChecks.h"
#include "servers/pathplanning/PathPlanningImpl.h"

namespace rgnav {
namespace {

RGNav::TaskInfo* answered(const Task& task) { return new RGNav::TaskInfo(toIdl(task)); }

}  // namespace

HighLevelPlanningImpl::HighLevelPlanningImpl(ServerRuntime& runtime, HighLevelPlanningService& service)
    : ServiceServant(runtime), service_(service) {}

RGNav::TaskInfo* HighLevelPlanningImpl::goTo(RGNav::RequestId request, const RGNav::PlanGoal& goal) {
  return serve(Raises::InvalidArgument, [&] {
    wire::requireId(request, "request");
    return answered(service_.goTo(request, checkedGoal(goal)));
  });
}

RGNav::TaskInfo* HighLevelPlanningImpl::explore(RGNav::RequestId request) {
  return serve(Raises::InvalidArgument, [&] {
    wire::requireId(request, "request");
    return answered(service_.explore(request));
  });
}

RGNav::TaskInfo* HighLevelPlanningImpl::stop(RGNav::RequestId request) {
  return serve(Raises::InvalidArgument, [&] {
    wire::requireId(request, "request");
    return answered(service_.stopAll(request));
  });
}

RGNav::TaskInfo* HighLevelPlanningImpl::cancel(RGNav::RequestId request, RGNav::TaskId id) {
  return serve(Raises::InvalidArgument | Raises::NotAvailable, [&] {
    wire::requireId(request, "request");
    return answered(service_.cancel(request, id));
  });
}

RGNav::TaskInfo* HighLevelPlanningImpl::task(RGNav::TaskId id) {
  return serve(Raises::InvalidArgument | Raises::NotAvailable, [&] {
    wire::requireId(id, "id");
    return answered(service_.task(id));
  });
}

RGNav::TaskInfoSeq* HighLevelPlanningImpl::tasks() {
  return serve(Raises::FailedOnly, [&] {
    return new RGNav::TaskInfoSeq(toIdlSeq<RGNav::TaskInfoSeq>(service_.tasks(), [](const Task& t) { return toIdl(t); }));
  });
}

RGNav::NamingQuestionSeq* HighLevelPlanningImpl::questions() {
  return serve(Raises::FailedOnly, [&] {
    return new RGNav::NamingQuestionSeq(toIdlSeq<RGNav::NamingQuestionSeq>(
        service_.questions(), [](const NamingQuestion& q) { return toIdl(q); }));
  });
}

void HighLevelPlanningImpl::answer(RGNav::RequestId request, RGNav::QuestionId question, const char* name) {
  serve(Raises::InvalidArgument | Raises::NotAvailable, [&] {
    wire::requireId(request, "request");
    wire::requireId(question, "question");
    service_.answer(request, question, wire::checkedName(name, "name", false));
  });
}

}  // namespace rgnav
