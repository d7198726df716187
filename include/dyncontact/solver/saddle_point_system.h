#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/base/linear_algebra.h>
#include <dyncontact/contact/contact_constraints.h>
#include <dyncontact/contact/multiplier_block.h>
#include <dyncontact/solver/direct_solver.h>
#include <dyncontact/solver/low_rank_update.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/partitioner.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <optional>
#include <vector>

namespace dyncontact
{
/**
 * The stiffness scales of an assembled K_eff (its displacement rows, constrained rows included),
 * [force/length]; 0 before the first assembly.
 */
struct TangentScales
{
  /** max_i |K_ii|: turns a constraint row's gap into a force (the line search's merit). */
  double largest_diagonal = 0.;
  /**
   * max_i sum_j |K_ij| (the infinity norm of those rows): the bound on the round-off of K u,
   * |fl(K u) - K u| <= n eps |K| |u|, of which the residual's round-off floor is made.
   */
  double largest_row_sum = 0.;

  template <class Archive>
  void serialize(Archive& archive, const unsigned int)
  {
    archive& largest_diagonal;
    archive& largest_row_sum;
  }
};

/**
 * The linear system of one Newton iteration of a contact step: the symmetric saddle-point matrix
 * [K_eff, -G^T; -G, -D] of size (n_dofs + n_multipliers)^2, unknowns ordered as the n_dofs
 * displacement DoFs of the DoFHandler followed by the contact multipliers (MultiplierBlock; row
 * n_dofs + j for multiplier j), and its direct solve. It is the one place that knows where the
 * multipliers sit: the contact layer writes its rows by multiplier (MultiplierRows), and
 * stack() and split() join and part vectors over all unknowns.
 *
 * The sparsity pattern is fixed at construction and never changes: the couplings of the
 * DoFHandler's cells plus those the contact layer declares
 * (ContactConstraints::for_each_coupling(), every candidate pair, active or not) and each
 * multiplier's diagonal. Parallel layout: rows are distributed like the DoFs, the multiplier rows
 * belong to the last MPI rank; each rank's pattern holds the full rows it writes (those of its
 * locally owned cells and, on the last rank, the constraint rows and the DoFs they couple to);
 * entries in rows owned elsewhere are sent on finish_assembly(). Vectors over all unknowns are
 * distributed like the rows (DistributedVector); stack() and split() join and part them.
 *
 * The direct solve keeps its factorization (DirectSolver; the symbolic analysis of the fixed
 * pattern is done by the constructor, in the set-up); update_factorization() brings it up to date
 * with the assembled matrix at the least cost, comparing the entries bit for bit with those
 * factorized:
 * - none changed (linear material, the same active set and pairs): the factors serve as they
 *   are, and the solution is the same to the last bit as with a fresh factorization;
 * - only entries in the rows and columns of at most max_low_rank_multipliers multipliers changed
 *   (pairs that entered or left the active set, with a linear material or a reused tangent): a
 *   LowRankUpdate of the factors (Sherman-Morrison-Woodbury; 2 right-hand sides per changed
 *   multiplier, solved in one call, instead of a factorization; the solution equal to round-off);
 * - otherwise: a new numeric factorization.
 *
 * Constrained DoFs (u_i = 0: e.g. u_r on a symmetry axis, AffineConstraints) have their rows and
 * columns eliminated by the assembly of the bodies (ElasticBodies), a positive diagonal left; the
 * contact layer's couplings to them are dropped here (add_coupling()), so that a zero right-hand
 * side there gives a zero increment.
 *
 * It owns the matrix, not its entries' meaning: what is assembled into it is the caller's
 * (DynamicResidual); it knows neither the bodies nor Newton's method.
 */
template <int dim>
class SaddlePointSystem : public MultiplierRows
{
public:
  /** The distributed matrix type (Epetra, through deal.II's wrapper). */
  using Matrix = TrilinosWrappers::SparseMatrix;

  /**
   * Builds the pattern and the distributed matrix (all entries zero) for the DoFs of
   * `dof_handler` and the multipliers of `contact` (their number is fixed from here on).
   * `constraints` (which must outlive this object) are the DoFs held at zero. The communicator
   * is the triangulation's.
   */
  SaddlePointSystem(const DoFHandler<dim>& dof_handler,
                    const ContactConstraints<dim>& contact,
                    const AffineConstraints<double>& constraints,
                    DirectSolverPackage package);

  /** The matrix, for adding entries of the leading block (displacement rows and columns). */
  Matrix& matrix() { return system_matrix; }

  /**
   * Where the contact layer writes the constraint rows (add_coupling(), add_diagonal()): this
   * system on the rank that owns the multiplier rows (the last rank), null elsewhere.
   */
  MultiplierRows* multiplier_rows() { return multiplier_rows_owner ? this : nullptr; }

  /**
   * Adds `value` at (row of `multiplier`, `dof`) and (`dof`, its column); nothing for a
   * constrained `dof`.
   */
  void add_coupling(unsigned int multiplier, types::global_dof_index dof, double value) override;
  /** Adds `value` at (row of `multiplier`, `dof`); nothing for a constrained `dof`. */
  void
  add_row_coupling(unsigned int multiplier, types::global_dof_index dof, double value) override;
  /** Adds `value` at (`dof`, column of `multiplier`); nothing for a constrained `dof`. */
  void
  add_column_coupling(unsigned int multiplier, types::global_dof_index dof, double value) override;
  /** Adds `value` at (row of `multiplier`, column of `other`). */
  void add_multiplier_coupling(unsigned int multiplier, unsigned int other, double value) override;

  /** Adds `value` on the diagonal of `multiplier`'s row. */
  void add_diagonal(unsigned int multiplier, double value) override;

  /**
   * Adds factor * diagonal[i] to the diagonal entry of each of this rank's displacement rows i
   * (`diagonal`: n_dofs entries, whole on every rank), e.g. the inertia c M of a lumped mass;
   * at the entries' known places, not by global index.
   */
  void add_to_diagonal(const Vector<double>& diagonal, double factor);

  /**
   * The vector over all unknowns, distributed like the rows (this rank's), of
   * `displacement_rows` (n_dofs entries, this rank's owned DoFs) followed by `multiplier_rows`
   * (n_multipliers entries, the same on every rank).
   */
  DistributedVector stack(const DistributedVector& displacement_rows,
                          const Vector<double>& multiplier_rows) const;

  /**
   * The parts of `stacked` (over all unknowns, distributed like the rows) that stack() joins:
   * the displacement rows into `displacement_part` (laid out over this rank's owned DoFs by the
   * caller), the multiplier rows into `multiplier_part` (resized; sent to every rank from the
   * last: collective).
   */
  void split(const DistributedVector& stacked,
             DistributedVector& displacement_part,
             Vector<double>& multiplier_part) const;

  /**
   * Starts an assembly: every entry set to the constant part (keep_as_constant_part()), or to
   * zero if none was kept (the pattern stays).
   */
  void start_assembly();

  /**
   * Keeps the matrix as assembled now (after finish_assembly(); every rank) as the constant part
   * every later start_assembly() starts from, e.g. K of linear bodies, which then is not added
   * again: a copy of this rank's values instead of an insertion of each entry by its global
   * index, and none of its entries sent between ranks. Collective.
   */
  void keep_as_constant_part() { constant_part = local_values(); }

  /** Whether keep_as_constant_part() was called. */
  bool has_constant_part() const { return !constant_part.empty(); }

  /**
   * Ends an assembly, also one that stopped early (a failed evaluation): exchanges the entries
   * added into rows owned by other ranks (a collective call).
   */
  void finish_assembly();

  /** The stiffness scales of the assembled K_eff, over all ranks. Collective. */
  TangentScales displacement_scales() const;

  /**
   * A low-rank update serves a matrix whose changes since the last factorization lie in the rows
   * and columns of at most this many multipliers (2 right-hand sides each, solved in one call: 8
   * single solves cost about half a factorization of the 13k-DoF spheres).
   */
  static constexpr unsigned int max_low_rank_multipliers = 4;

  /** What update_factorization() did. */
  enum class Update
  {
    none,          ///< the matrix is the one the solver already serves
    low_rank,      ///< a low-rank update of the last factorization
    factorization, ///< a new numeric factorization
  };

  /**
   * Brings the solver up to date with the assembled matrix (class documentation; collective) and
   * says how; a low-rank update only if `allow_low_rank` (else any change is factorized, and the
   * solutions are those of fresh factorizations to the last bit). The time goes to the phase
   * "factorization" or "low-rank update" of `timer` if given. Throws SolverFailure if the
   * factorization fails, e.g. for a singular matrix.
   */
  Update update_factorization(bool allow_low_rank, TimerOutput* timer = nullptr);

  /**
   * Solves matrix * solution = right_hand_side with the solver of the last update_factorization()
   * (which must have been called since the last assembly); both vectors have
   * n_dofs + n_multipliers entries, distributed like the rows (stack(), split()). Collective;
   * throws SolverFailure if the solve fails.
   */
  DistributedVector solve(const DistributedVector& right_hand_side);

  /** The number of numeric factorizations so far. */
  unsigned int n_factorizations() const { return direct_solver.n_factorizations(); }

  /** The direct solver's figures of its last factorization (DirectSolver), or empty. */
  std::string last_factorization_statistics() const
  {
    return direct_solver.last_factorization_statistics();
  }

  /** The number of low-rank updates so far. */
  unsigned int n_low_rank_updates() const { return low_rank_updates; }

  /** Wall time [s] of the direct solver's symbolic analysis, done by the constructor. */
  double analysis_time() const { return analysis_wall_time; }

private:
  /** This rank's matrix entries, row by row. */
  std::vector<double> local_values() const;

  /** Sets this rank's matrix entries, row by row (as local_values() gives them). */
  void set_local_values(const std::vector<double>& values);

  /**
   * The low-rank update from the factorized matrix to the assembled one, if the changes qualify
   * (class documentation) and the update is well conditioned; empty otherwise. Collective.
   */
  std::optional<LowRankUpdate> low_rank_update_of_changes();

  const MPI_Comm communicator;
  const types::global_dof_index n_dofs;
  const unsigned int n_multipliers;
  const bool multiplier_rows_owner;
  /** The locally owned DoFs of the DoFHandler (the displacement rows of this rank). */
  const IndexSet locally_owned_dofs;
  /** This rank's rows: its DoFs and, on the last rank, the multiplier rows (one range). */
  IndexSet locally_owned_rows;
  /** The layout of vectors over the rows, as the direct solver takes them. */
  std::shared_ptr<const Utilities::MPI::Partitioner> row_partitioner;
  const AffineConstraints<double>& constraints;
  Matrix system_matrix;
  DirectSolver direct_solver;
  /**
   * Of each of this rank's rows (Epetra's local numbering), the diagonal entry's place in the
   * row, or -1 in the multiplier rows.
   */
  std::vector<int> diagonal_position;
  /** This rank's entries (row by row) of the constant part; empty if none was kept. */
  std::vector<double> constant_part;
  /** This rank's matrix entries (row by row) at the last factorization; empty before the first. */
  std::vector<double> factorized_values;
  /** This rank's matrix entries at the last update_factorization(). */
  std::vector<double> served_values;
  /** The update from the factorized matrix to the served one, if it is not the factorized one. */
  std::optional<LowRankUpdate> low_rank;
  unsigned int low_rank_updates = 0;
  double analysis_wall_time     = 0.;
};
} // namespace dyncontact
