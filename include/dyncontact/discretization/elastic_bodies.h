#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/base/linear_algebra.h>
#include <dyncontact/discretization/kinematics.h>
#include <dyncontact/discretization/sparse_variation.h>
#include <dyncontact/material/material.h>

#include <deal.II/base/partitioner.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <vector>

namespace dyncontact
{
/** The constitutive data of one body: its hyperelastic law and reference mass density. */
struct BodyMaterial
{
  std::shared_ptr<const Material> material;
  double density;
};

/**
 * The elastic bodies of a problem on one DoFHandler (body b = cells with material id b): the
 * lumped mass, the internal force Q(u), its tangent dQ/du and the strain energy, all in the
 * total-Lagrangian setting. It knows neither contact nor time stepping.
 *
 * Parallel: every MPI rank integrates its locally owned cells, reading the displacement of their
 * DoFs owned elsewhere as ghosts; Q goes to the owners of its DoFs (each rank holds its owned
 * DoFs) and the energy is summed over the ranks; the lumped mass is summed over the ranks and held
 * whole on every rank. The tangent goes into a distributed Trilinos matrix (entries in rows owned
 * elsewhere are sent on compress()).
 *
 * The lumped mass is the HRZ (Hinton-Rock-Zienkiewicz) diagonal: per cell, the diagonal of the
 * consistent mass scaled so that each component's entries sum to the cell's mass. It is positive
 * at every node, also on the symmetry axis of an axisymmetric model, where nodal (Gauss-Lobatto)
 * quadrature would give zero because the measure 2 pi r vanishes there; for 2-node bars and
 * plane 9-node quadrilaterals it equals the nodal-quadrature lumping (1/2, 1/2 and 1/36, 1/9, 4/9).
 *
 * Speed: the reference configuration never moves (total Lagrangian), so the shape values and
 * gradients, the points and the weights dV = JxW times the kinematics' measure factor at every
 * quadrature point of every locally owned cell, with each shape function's deformation gradient
 * variation (SparseVariation), are computed once, at construction (about 9 KB per axisymmetric Q2
 * cell: 200 MB for 200k DoFs), and each evaluation is arithmetic on them. The cells are
 * integrated on the threads of deal.II's MultithreadInfo (WorkStream); their contributions are
 * added to the global vector, matrix and energy in cell order, so this integration gives the same
 * bits on any number of threads. (The executable runs one thread: with two, the bar histories
 * differed from t = 0 in the kinetic energy, outside this class; not yet traced.)
 *
 * Linear bodies: if every body's material is linear (Material::is_linear(); the kinematics give
 * F = I + a term linear in u), the tangent dQ/du = K is constant: add_constant_tangent()
 * integrates it (this rank's cells' share, entries summed in cell order as in every assembly, so
 * the same bits), once, and the caller keeps it (DynamicResidual: as SaddlePointSystem's constant
 * part, which every tangent starts from). Q(u) itself is still integrated point by point
 * rather than taken as K u: the product K u of a large rigid translation (the spheres move by 2
 * before they touch) leaves round-off forces of eps |K| |u| that do not balance, and in 800
 * free-flight steps they changed the momentum by 4e-10 of itself; the quadrature's stay balanced.
 */
template <int dim>
class ElasticBodies
{
public:
  /**
   * The bodies of `dof_handler`'s cells (material id b: bodies[b]). If `constraints` is given (it
   * must outlive this object), every tangent goes through it
   * (AffineConstraints::distribute_local_to_global): the rows and columns of its constrained DoFs
   * (u_i = 0: the axis, clamps) get no entry but a positive diagonal, so that a zero right-hand
   * side there gives a zero increment and the other rows do not see those DoFs.
   */
  ElasticBodies(const DoFHandler<dim>& dof_handler,
                const Mapping<dim>& mapping,
                const Kinematics<dim>& kinematics,
                std::vector<BodyMaterial> bodies,
                const AffineConstraints<double>* constraints = nullptr);

  /**
   * Diagonal of the lumped mass matrix [mass], one entry per DoF, on every rank. The DoFs flagged
   * in `massless_dofs` (empty, or n_dofs entries) get zero: each cell's lumped mass of them goes to
   * the cell's other DoFs of the same component in proportion to theirs, so each cell keeps its
   * mass per component (mass redistribution, Khenous, Laborde & Renard 2008). Throws InputError if
   * a cell has every DoF of a component massless.
   */
  Vector<double> lumped_mass(const std::vector<bool>& massless_dofs = {}) const;

  /**
   * Internal force Q(u) at `displacement` (this rank's owned DoFs; the other DoFs of its cells
   * are fetched from their owners) into `internal_force` (reinitialized: the rank's owned DoFs, the
   * sums over all ranks' cells; collective) and, if `tangent` is not null, dQ/du added into its
   * leading n_dofs x n_dofs block (the caller zeroes it; linear bodies are better served by
   * add_constant_tangent() once), and, if `strain_energy` is not null, the strain energy from the
   * same pass.
   */
  void assemble_internal_force(const DistributedVector& displacement,
                               DistributedVector& internal_force,
                               TrilinosWrappers::SparseMatrix* tangent,
                               double* strain_energy = nullptr) const;

  /** Whether dQ/du is constant: every body's material is linear (class documentation). */
  bool has_constant_tangent() const { return constant_tangent; }

  /**
   * Bodies with a constant tangent (has_constant_tangent()): adds K, this rank's cells' share,
   * into the leading block of `tangent` (an integration at u = 0; the caller keeps it, e.g. as
   * SaddlePointSystem's constant part). Collective.
   */
  void add_constant_tangent(TrilinosWrappers::SparseMatrix& tangent) const;

  /**
   * Total strain energy, the integral of W(F) over all bodies, at `displacement` (this rank's
   * owned DoFs). Collective.
   */
  double strain_energy(const DistributedVector& displacement) const;

  /**
   * An upper bound [1/time] of the highest angular frequency of the undeformed bodies (the
   * tangent K at u = 0) with the lumped mass of lumped_mass(`massless_dofs`), the DoFs flagged in
   * `fixed_dofs` (n_dofs entries) held at zero: max over the cells of sqrt(lambda_max(K_e, M_e))
   * on the cell's DoFs that are neither fixed nor massless, K_e and M_e the cell's stiffness and
   * lumped mass (the element eigenvalue inequality, Irons & Treharne 1971; Hughes, The Finite
   * Element Method, 2000, sec. 9.1.3: x.K x = sum_e x_e.K_e x_e <= max_e lambda_e x.M x). A
   * massless DoF is held at zero in its cell's quotient, which only raises the global one's
   * bound (the massless DoFs minimize the energy). Sharp for uniform meshes of 2-node bars
   * (2 c / h); for square Q2 cells it is the 2D mode the 1D chain estimate 2 sqrt(6) c / h misses.
   * Large deformation changes K: the energy guard watches the run beyond this linear bound.
   */
  double highest_frequency_bound(const std::vector<bool>& fixed_dofs,
                                 const std::vector<bool>& massless_dofs = {}) const;

private:
  /**
   * The lumped (HRZ) masses of the local DoFs of the cell `fe_values` was reinitialized on,
   * density `density`, with the mass of the DoFs flagged in `massless` (local, n_local entries)
   * moved to the cell's other DoFs of the same component (see lumped_mass()).
   */
  std::vector<double> cell_lumped_mass(const FEValues<dim>& fe_values,
                                       types::material_id body,
                                       const std::vector<bool>& massless) const;

  /**
   * One pass over all quadrature points filling whichever of the outputs is not null, at
   * `displacement` in force_layout with its ghosts updated (with_cell_ghosts()); `tangent`
   * is a TrilinosWrappers::SparseMatrix or (for K of linear bodies) a SparseMatrix<double>.
   */
  template <typename MatrixType>
  void integrate(const DistributedVector& displacement,
                 DistributedVector* internal_force,
                 MatrixType* tangent,
                 double* strain_energy) const;

  /** A locally owned cell's reference data at its quadrature points (class documentation). */
  struct CellData
  {
    types::material_id body;
    std::vector<types::global_dof_index> dofs;
    /** The same DoFs' local indices in force_layout (owned, then ghosts). */
    std::vector<unsigned int> local_dofs;
    /** Per quadrature point q: X_q, dV_q; shape value, gradient and delta F of local DoF i at
     *  index q * n_local + i. */
    std::vector<Point<dim>> points;
    std::vector<double> volumes;
    std::vector<double> shape_values;
    std::vector<Tensor<1, dim>> shape_gradients;
    std::vector<SparseVariation> variations;
  };

  const DoFHandler<dim>& dof_handler;
  const Mapping<dim>& mapping;
  const Kinematics<dim>& kinematics;
  std::vector<BodyMaterial> bodies;
  /** The tangent goes through these (null: none), see the constructor. */
  const AffineConstraints<double>* constraints;
  /** The FE component of each local DoF. */
  std::vector<unsigned int> local_component;
  std::vector<CellData> cells;
  /**
   * The layout of the internal force and of the displacement the cells read: this rank's owned
   * DoFs, and as ghosts the other DoFs of its cells (their force contributions are sent to the
   * owners, their displacements fetched from them).
   */
  std::shared_ptr<const Utilities::MPI::Partitioner> force_layout;

  /** `displacement` (owned DoFs) in force_layout, its ghosts updated (collective). */
  DistributedVector with_cell_ghosts(const DistributedVector& displacement) const;

  /** Every body's material is linear: dQ/du = K is constant (has_constant_tangent()). */
  bool constant_tangent;
};
} // namespace dyncontact
