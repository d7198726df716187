#pragma once

#include <dyncontact/base/global.h>
#include <dyncontact/discretization/kinematics.h>
#include <dyncontact/material/material.h>

#include <deal.II/numerics/data_postprocessor.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace dyncontact
{
/**
 * Stress and strain at the output points of a displacement field, for DataOut: from the
 * deformation gradient F of the kinematics and the first Piola-Kirchhoff stress P of each body's
 * material (cell material id b = body b), it writes
 *  - `cauchy_stress_<ij>` [force/area]: the Cauchy (true) stress sigma = P F^T / det F;
 *  - `green_lagrange_strain_<ij>` [-]: E = (F^T F - I) / 2, in the reference axes;
 *  - `von_mises_stress` [force/area]: sqrt(3/2 s:s) of the deviator s of the full 3x3 sigma.
 * The components ij are those a model of this dimension can make nonzero: xx (bars); rr, zz,
 * thetatheta (hoop), rz for axisymmetry (xx, yy, zz, xy in plane strain); all six in 3D. Axis names
 * come from Kinematics::axis_names(). The values are evaluated per cell, so they are discontinuous
 * across cells as the finite element stress is; no smoothing or projection.
 */
template <int dim>
class StressPostprocessor : public DataPostprocessor<dim>
{
public:
  /** `materials[b]` is the law of body b; both arguments must outlive the object. */
  StressPostprocessor(const Kinematics<dim>& kinematics,
                      std::vector<std::shared_ptr<const Material>> materials);

  void evaluate_vector_field(const DataPostprocessorInputs::Vector<dim>& inputs,
                             std::vector<Vector<double>>& computed_quantities) const override;
  /** deal.II calls this one for a one-component (1D) displacement. */
  void evaluate_scalar_field(const DataPostprocessorInputs::Scalar<dim>& inputs,
                             std::vector<Vector<double>>& computed_quantities) const override;
  std::vector<std::string> get_names() const override;
  std::vector<DataComponentInterpretation::DataComponentInterpretation>
  get_data_component_interpretation() const override;
  UpdateFlags get_needed_update_flags() const override;

private:
  /** sigma, E and the von Mises stress of `material` at F into `out`, in get_names() order. */
  void evaluate(const Material& material, const Tensor<2, 3>& F, Vector<double>& out) const;

  const Kinematics<dim>& kinematics;
  std::vector<std::shared_ptr<const Material>> materials;
  /** The (i, j) of the written components, i <= j, indices into the 3x3 tensors. */
  std::vector<std::pair<unsigned int, unsigned int>> components;
};
} // namespace dyncontact
