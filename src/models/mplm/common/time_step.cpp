#include "models/mplm/common/time_step.hpp"

#include <iomanip>
#include <sstream>

namespace pdq::mplm {

void reportTimeStep(Context& ctx, const char* model, double omegaMax, double stable,
                    double thesisDt) {
  ctx.setStableDt(stable);
  if (ctx.root()) {  // formatted apart: the log's own precision stays as it was
    std::ostringstream line;
    line << std::setprecision(4) << model << ": highest frequency " << omegaMax
         << " rad/s, stable dt " << stable << " s, s/(pi c0) = " << thesisDt << " s, using dt "
         << ctx.dt() << " s\n";
    ctx.log() << line.str();
  }
  if (ctx.dt() > stable) {
    std::ostringstream os;
    os << std::setprecision(4) << model << ": dt = " << ctx.dt()
       << " s exceeds the stable time step " << stable
       << " s: the run will blow up; lower dt, or leave it out to use dt_safety x the stable "
          "step";
    ctx.warn(os.str());
  }
}

}  // namespace pdq::mplm
