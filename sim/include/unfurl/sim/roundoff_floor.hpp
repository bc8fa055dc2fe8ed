// The right-hand side's round-off: the smallest change of f a run can
// resolve. Tolerances below it make the integrator chase noise (steps
// shrink until the noise fits inside the error test). With loops it is set
// by the true gap's round-off, which grows with the loops' length, times the
// regulator's v_max^2: 1.8e-11 on the reference pantograph, 3.6e-10 on a
// 100-stage one with the reference's springs and v_max; trees' are near
// 1e-19. Measured steps agree: the pantograph's grow 6-fold from rtol 1e-10
// to 1e-11, that 100-stage array's 8-fold from 1e-9 to 1e-10.
#pragma once

#include <vector>

namespace unfurl::sim {

class Dynamics;

// Estimated at the state y from second differences along three fixed
// directions, with steps exact in floating point (y1 = fl(y + e v),
// y2 = y + 2 (y1 - y)), so that what remains of f(y2) - 2 f(y1) + f(y) is
// the evaluation's own error. Each component is measured in its state's
// scale per the mechanism's time scale (Dynamics::state_scale() x rate), the
// measure rtol and atol are in, and the root mean square over components
// taken, as the integrators' error norms take it; the largest over the
// directions. Independent errors of standard deviation sigma give second
// differences of sqrt(6) sigma, so this is about 2.5 sigma: a floor with a
// margin, which is where the measured step counts jump. 0 where f cannot
// be evaluated there.
double roundoff_floor(Dynamics& dynamics, double t, const std::vector<double>& y);

}  // namespace unfurl::sim
