#include "analysis/eprint_log.hpp"

#include <cstdio>
#include <string>

namespace openmss::analysis {

void EprintLog::attach(solvers::Integrator& integrator) {
  integrator.setStepObserver(&EprintLog::onStep, this);
  integrator.setIterationObserver(&EprintLog::onIteration, this);
}

void EprintLog::onStep(const solvers::BdfStepInfo& info, void* self) {
  auto& me = *static_cast<EprintLog*>(self);
  using Event = solvers::BdfStepInfo::Event;
  char buf[200];
  switch (info.event) {
    case Event::Attempt:
      std::snprintf(buf, sizeof buf, " EPRINT step %ld: order %d, time %.9E, step size %.6E",
                    info.step, info.order, info.time, info.stepSize);
      break;
    case Event::Accepted:
      std::snprintf(buf, sizeof buf, "   step %ld accepted: local error %.3E of the tolerance",
                    info.step, info.errorNorm);
      break;
    case Event::ErrorTestFailed:
      std::snprintf(buf, sizeof buf,
                    "   step %ld rejected: local error %.3E of the tolerance; retrying with a "
                    "smaller step",
                    info.step, info.errorNorm);
      break;
    case Event::CorrectorFailed:
      std::snprintf(buf, sizeof buf,
                    "   step %ld rejected: the corrector did not converge; retrying with a "
                    "smaller step",
                    info.step);
      break;
  }
  me.log_.line(buf);
}

void EprintLog::onIteration(const solvers::BdfIterationInfo& info, void* self) {
  auto& me = *static_cast<EprintLog*>(self);
  char buf[80];
  std::snprintf(buf, sizeof buf, "   iteration %d: largest residual %.3E in ", info.iteration,
                info.worstResidual);
  std::string line = buf + me.problem_.equationName(info.worstEquation);
  std::snprintf(buf, sizeof buf, "; largest change %.3E in ", info.worstChange);
  line += buf + me.problem_.variableName(info.worstVariable);
  me.log_.line(line);
}

}  // namespace openmss::analysis
