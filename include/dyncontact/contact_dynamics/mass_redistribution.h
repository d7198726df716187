#pragma once

#include <dyncontact/contact_dynamics/contact_dynamics.h>

namespace dyncontact
{
/**
 * Contact/dynamics = mass-redistribution: the nodes that can come into contact carry no mass
 * (Khenous, Laborde & Renard, Eur. J. Mech. A/Solids 27 (2008) 918-932; Hager, Hüeber & Wohlmuth,
 * IJNME 73 (2008) 205-225). With a singular mass matrix on the contact nodes the semi-discrete
 * problem is a differential-algebraic system whose contact nodes follow the others
 * quasi-statically: the contact force is the elastic force of the adjacent elements, without the
 * impulsive part that makes the contact force of a massive node oscillate (paper 6.1: the
 * classical scheme's force alternates about the exact 0.5).
 *
 * The mass: ElasticBodies::lumped_mass() with the DoFs of every node a candidate pair can couple
 * (ContactConstraints::contact_dofs(), both sides) massless; each cell's lumped mass of those DoFs
 * goes to the cell's other DoFs of the same component, in proportion to their lumped masses, so
 * every cell keeps its mass per component (the total mass and momentum of a uniform velocity are
 * unchanged; a body's centre of mass moves by less than one contact element's size times that
 * element's share of the body's mass).
 *
 * The rates: at a massless DoF the equation of motion is an equilibrium, and its Newmark rates do
 * not enter the solution (they multiply a zero mass); they are set, after every step, to the
 * step's backward differences v_{n+1} = (u_{n+1} - u_n)/dt and a_{n+1} = (v_{n+1} - v_n)/dt, so
 * that the next predictor extrapolates the motion linearly (exact in free flight) and the
 * histories show the nodes' actual motion. Every DoF with mass keeps the classical rates.
 *
 * Assumptions: Lagrange multipliers or penalty; not combined with another treatment (the
 * Taylor-Papadopoulos correction weighs the pair nodes by their masses, here zero). Every cell
 * needs a node off the contact surfaces (true of Q2 cells and of bars of two or more elements);
 * otherwise ElasticBodies::lumped_mass() throws InputError.
 */
template <int dim>
class MassRedistribution : public ContactDynamics<dim>
{
public:
  bool contact_nodes_massless() const override { return true; }

  /**
   * The contact nodes are massless in every direction, so their tangential rates, like the
   * normal ones, follow from the displacements (Hager, Hueber & Wohlmuth 2008 carry Coulomb
   * friction on such a modified mass).
   */
  bool carries_friction() const override { return true; }

  void correct_rates(const RateMap& rates,
                     const ContactConstraints<dim>& contact,
                     const Vector<double>& lumped_mass,
                     const StepStates& step,
                     Vector<double>& v_new,
                     Vector<double>& a_new) const override;
};
} // namespace dyncontact
