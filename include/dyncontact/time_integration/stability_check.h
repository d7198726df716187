#pragma once

#include <dyncontact/time_integration/generalized_alpha.h>

namespace dyncontact
{
/**
 * The time step against the stability limit of conditionally stable Newmark (2 beta < gamma:
 * stable for omega dt <= 1/sqrt(gamma/2 - beta), GeneralizedAlpha::stability_limit(); no limit
 * otherwise). `body_omega_dt` bounds the bodies' highest mode (ElasticBodies'
 * element-eigenvalue bound times dt), `spring_omega_dt` the stiffest penalty spring's (0 without
 * springs); a spring adds its stiffness to the mesh's, so the coupled highest mode is bounded by
 * their hypotenuse (Weyl's inequality on M^-1/2 (K + K_penalty) M^-1/2). `penalty_lowered`: the
 * automatic penalty holds its springs at omega dt = 1, so that case needs room for it below the
 * limit. Throws InputError naming Time integration/time step (or Contact/penalty factor = auto)
 * and the largest step that passes, rounded down to 6 digits so that the printed step passes.
 * Accepts omega dt up to the limit times 1 + 1e-12 (the round-off of a step printed at the limit).
 */
void check_stability(const GeneralizedAlpha& integrator,
                     double body_omega_dt,
                     double spring_omega_dt,
                     bool penalty_lowered);
} // namespace dyncontact
