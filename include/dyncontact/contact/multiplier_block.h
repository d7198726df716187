#pragma once

#include <dyncontact/base/global.h>

#include <vector>

namespace dyncontact
{
/**
 * The layout of the contact multipliers: candidate pair k owns n_components(k) consecutive
 * multipliers from index(k, 0) on: 1 for a normal contact constraint (the one kind today), dim
 * for a pair that also constrains the tangential motion (friction, tied contact). The multipliers
 * are numbered 0 .. n_multipliers() - 1 here; where they sit among the unknowns of the
 * saddle-point system is the system's business (SaddlePointSystem).
 */
class MultiplierBlock
{
public:
  /** No pairs. */
  MultiplierBlock() = default;

  /** One pair per entry of `components_per_pair` (each >= 1), with that many multipliers. */
  explicit MultiplierBlock(const std::vector<unsigned int>& components_per_pair);

  unsigned int n_pairs() const { return first.size() - 1; }
  unsigned int n_multipliers() const { return first.back(); }
  unsigned int n_components(const unsigned int pair) const { return first[pair + 1] - first[pair]; }

  /** The multiplier of component `component` (< n_components(pair)) of `pair`. */
  unsigned int index(const unsigned int pair, const unsigned int component = 0) const
  {
    return first[pair] + component;
  }

private:
  std::vector<unsigned int> first = {0}; ///< first multiplier of each pair, then the total
};

/**
 * Where the contact layer writes its rows and columns of the saddle-point matrix, by multiplier
 * (MultiplierBlock) and displacement DoF; the matrix's owner (SaddlePointSystem) knows where the
 * multipliers' rows are. The matrix is symmetric unless a pair has friction: a sliding pair's
 * tangential row (CoulombFriction) differs from its column, and couples its pair's multipliers.
 */
class MultiplierRows
{
public:
  virtual ~MultiplierRows() = default;

  /** Adds `value` at (multiplier row, `dof`) and at (`dof`, multiplier column), in that order. */
  virtual void add_coupling(unsigned int multiplier, types::global_dof_index dof, double value) = 0;

  /** Adds `value` at (multiplier row, `dof`) only. */
  virtual void
  add_row_coupling(unsigned int multiplier, types::global_dof_index dof, double value) = 0;

  /** Adds `value` at (`dof`, multiplier column) only. */
  virtual void
  add_column_coupling(unsigned int multiplier, types::global_dof_index dof, double value) = 0;

  /**
   * Adds `value` at (row of `multiplier`, column of `other`), two multipliers of the same pair
   * (any two of a pair are in the pattern).
   */
  virtual void
  add_multiplier_coupling(unsigned int multiplier, unsigned int other, double value) = 0;

  /** Adds `value` on the diagonal of `multiplier`'s row. */
  virtual void add_diagonal(unsigned int multiplier, double value) = 0;
};
} // namespace dyncontact
