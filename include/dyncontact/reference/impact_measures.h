#pragma once

#include <vector>

namespace dyncontact
{
/**
 * The figures of one impact, measured from a sampled contact-force history, that are compared with
 * Hertz's theory (HertzImpact), plus a measure of how much the force rings. See
 * measure_impact() for the definitions.
 */
struct ImpactMeasures
{
  /// The largest force, refined by a parabola through the largest sample and its neighbours.
  double peak_force;
  /// The time of peak_force.
  double peak_time;
  /// The sub-step estimate of the time the contact begins.
  double contact_start;
  /// The sub-step estimate of the time the contact ends.
  double contact_end;
  /// contact_end - contact_start.
  double duration;
  /// The trapezoidal integral of the force over all samples.
  double impulse;
  /// The RMS amplitude of the period-2 oscillation in contact relative to peak_force (no unit).
  double ringing;
  /// The number of samples with a positive force (all of them lie in the contact interval).
  unsigned int contact_samples;
};

/**
 * The ImpactMeasures of the contact-force history @p force sampled at @p times: F_n = F(t_n),
 * compression positive and zero outside contact, as computed by an implicit Newmark time
 * integrator for one impact. The steps t_{n+1} - t_n may differ (a run whose step control cut
 * some steps records every sub-step); the formulas below are written for a uniform step dt and
 * take each step's own size where they need one.
 *
 * Definitions, with the reasoning behind them:
 *
 * - Contact interval: from the first to the last sample with F > 0. The classical Newmark scheme
 *   may chatter, i.e. release the contact for a step and close it again; such zeros stay inside
 *   the one interval, so an impact is never split into several. A negative force (tension, or
 *   round-off of a multiplier) counts as no contact here but enters the impulse and the ringing as
 *   it is. contact_samples counts the samples with F > 0 only.
 *
 * - contact_start and contact_end: Hertz's law F = K d^{3/2}, with the approach d linear in t near
 *   first touch and near separation (d'' is proportional to d^{3/2}, which vanishes there), makes
 *   F^{2/3} linear in t at both ends of the contact. So F^{2/3} is extrapolated linearly to zero
 *   through the first two positive samples (for the end: the last two). For the exact Hertz
 *   history the residual curvature, d = v t (1 - (t / T)^{5/2} / 7 + ...) with T = d_max / v,
 *   makes this estimate early by at most 1.5 T (dt / T)^{7/2}, far below a step. The estimate is
 *   clamped to the step before the first positive sample (after the last): if there are fewer than
 *   two positive samples, if F^{2/3} does not increase into the contact, or if the extrapolated
 *   zero lies more than one step away, contact_start is the time of the last sample before the
 *   contact (contact_end: of the first sample after it), where F <= 0 was observed. A history that
 *   begins (ends) in contact has no such sample; contact_start (contact_end) is then its first
 *   (last) sample time, and the true start (end) is unknown. duration = contact_end -
 *   contact_start.
 *
 * - peak_force and peak_time: the parabola through the largest sample (the first, for ties) and
 *   its two neighbours has its vertex within half a step of the largest sample; its value there
 *   estimates a smooth peak with an error of order dt^4 F'''' instead of the order dt^2 F'' of the
 *   raw maximum (with unequal steps the parabola through the three samples, of order dt^3 F''').
 *   If a neighbour is missing or the parabola is not concave (a flat top), the raw
 *   largest sample and its time are returned.
 *
 * - impulse: the trapezoidal rule over all samples, dt (F_0 / 2 + F_1 + ... + F_{N-1} / 2) for a
 *   uniform step, the sum of (t_{n+1} - t_n) (F_n + F_{n+1}) / 2 in general. For
 *   Newmark with gamma = 1/2 the velocity update is M (v_{n+1} - v_n) = dt (f_n + f_{n+1}) / 2, so
 *   this sum equals the change of momentum that the contact force causes exactly, not just to
 *   within a quadrature error. (For a smooth F that vanishes with F' = 0 at both ends, like
 *   Hertz's, the trapezoidal rule is also accurate to order dt^{5/2} relative.)
 *
 * - ringing: the RMS, over the samples n whose centred 5-point window n-2..n+2 lies entirely in the
 *   contact interval, of the period-2 component
 *
 *     P_n = (F_{n-2} - 4 F_{n-1} + 6 F_n - 4 F_{n+1} + F_{n+2}) / 16,
 *
 *   divided by peak_force; zero if no sample has such a window (fewer than 5 samples in the contact
 *   interval). Only windows of four equal steps count (to 1e-9 of a step plus the round-off of the
 *   times): across a change of step size the 4th difference is no period-2 measure. P_n is the
 *   4th difference over 16; equivalently, 35/48 of the residual F_n - A_n,
 *   where A_n is the value at t_n of the least-squares parabola through the 5 samples (the
 *   Savitzky-Golay smoothing (-3, 12, 17, 12, -3) / 35). Why it measures the ringing:
 *   a period-2 oscillation F_n = F0 (1 + e (-1)^n) has 4th difference 16 F0 e (-1)^n, so P_n =
 *   F0 e (-1)^n and the ringing is e F0 / peak_force: the relative amplitude of the oscillation
 *   (for an amplitude varying along the contact, its RMS). A smooth force resolved by many steps
 *   gives P_n = dt^4 F''''(t_n) / 16 + ..., tiny: for the exact Hertz history at 25-30 steps per
 *   contact it is below 1e-3 of the peak, and its largest values come from the windows next to the
 *   ends, where F ~ t^{3/2} is least smooth (P_n / F_max <= 0.012 (dt / T)^{3/2}, with T as above).
 *   The plain centred 5-point moving average A_n = (F_{n-2} + ... + F_{n+2}) / 5 was not used: its
 *   residual on a period-2 oscillation is F0 e (-1)^n (1 - 1/5), i.e. 0.8 e, but on a smooth curve
 *   it is -dt^2 F'' (the moving average's weights have second moment 2 dt^2), about 2 (dt / T)^2 at
 *   the Hertz peak and an RMS of 1 to 1.5 % of the peak at 25-30 steps per contact. That floor is
 *   as large as the oscillation it should reveal; the 4th difference removes every cubic exactly.
 *
 * Input errors throw std::invalid_argument with a message saying what is wrong: sizes of @p times
 * and @p force that differ, fewer than 3 samples, a non-finite time or force, and times that do
 * not increase strictly. A history without
 * any positive force is not an error: the spheres never touched, and the result is all zeros
 * (including the impulse) with contact_samples = 0.
 *
 * This is what it is NOT: not a check that the history comes from Newmark or from Hertz's law (any
 * sampled force is measured; only the justification of the contact ends and of the impulse rests
 * on them), not a measure of oscillations slower than period 2 (those pass as smooth force), and
 * not meant for several separate impacts in one history (they would merge into one interval).
 */
ImpactMeasures measure_impact(const std::vector<double>& times, const std::vector<double>& force);
} // namespace dyncontact
