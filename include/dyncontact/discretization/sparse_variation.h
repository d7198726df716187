#pragma once

#include <deal.II/base/exceptions.h>
#include <deal.II/base/tensor.h>

namespace dyncontact
{
using namespace dealii;

/**
 * The nonzero entries of one shape function's deformation gradient variation delta F (3 x 3), in
 * row-major order: it has 1 (bar), 2 (plane), 3 (axisymmetric radial: with the hoop term; solid)
 * of the 9, which is all it can hold. Products with it run over these entries only, in the order
 * of deal.II's full tensor products, so that they give the same bits at a fraction of the work.
 */
class SparseVariation
{
public:
  SparseVariation() = default;

  /** The nonzero entries of `variation`; at most 3 (ExcMessage otherwise). */
  explicit SparseVariation(const Tensor<2, 3>& variation)
  {
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
        if (variation[a][b] != 0.)
        {
          AssertThrow(n_entries < capacity,
                      ExcMessage("A deformation gradient variation has more than 3 nonzero "
                                 "entries."));
          row[n_entries]    = a;
          column[n_entries] = b;
          value[n_entries]  = variation[a][b];
          ++n_entries;
        }
  }

  /**
   * A : delta F, summed as deal.II's scalar_product() does (over rows, then columns within a
   * row, from zero): leaving out the zero terms changes no bit of the sum.
   */
  double contract(const Tensor<2, 3>& tensor) const
  {
    double sum = 0.;
    for (unsigned int e = 0; e < n_entries;)
    {
      const unsigned int a = row[e];
      double row_sum       = 0.;
      for (; e < n_entries && row[e] == a; ++e)
        row_sum += tensor[a][column[e]] * value[e];
      sum += row_sum;
    }
    return sum;
  }

private:
  static constexpr unsigned int capacity = 3;
  unsigned char n_entries                = 0;
  unsigned char row[capacity]            = {};
  unsigned char column[capacity]         = {};
  double value[capacity]                 = {};
};
} // namespace dyncontact
