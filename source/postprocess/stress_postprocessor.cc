#include <dyncontact/base/dimensions.h>
#include <dyncontact/postprocess/stress_postprocessor.h>

#include <deal.II/base/symmetric_tensor.h>

#include <cmath>

namespace dyncontact
{
template <int dim>
StressPostprocessor<dim>::StressPostprocessor(
    const Kinematics<dim>& kinematics, std::vector<std::shared_ptr<const Material>> materials)
    : kinematics(kinematics), materials(std::move(materials))
{
  for (unsigned int i = 0; i < dim; ++i)
    components.emplace_back(i, i);
  if (dim == 2)
    components.emplace_back(2, 2); // hoop (axisymmetry) or out-of-plane (plane strain)
  for (unsigned int i = 0; i < dim; ++i)
    for (unsigned int j = i + 1; j < dim; ++j)
      components.emplace_back(i, j);
}

template <int dim>
std::vector<std::string> StressPostprocessor<dim>::get_names() const
{
  const std::array<std::string, 3> axes = kinematics.axis_names();
  std::vector<std::string> names;
  for (const std::string quantity : {"cauchy_stress_", "green_lagrange_strain_"})
    for (const auto& [i, j] : components)
      names.push_back(quantity + axes[i] + axes[j]);
  names.emplace_back("von_mises_stress");
  return names;
}

template <int dim>
std::vector<DataComponentInterpretation::DataComponentInterpretation>
StressPostprocessor<dim>::get_data_component_interpretation() const
{
  return std::vector<DataComponentInterpretation::DataComponentInterpretation>(
      2 * components.size() + 1, DataComponentInterpretation::component_is_scalar);
}

template <int dim>
UpdateFlags StressPostprocessor<dim>::get_needed_update_flags() const
{
  return update_values | update_gradients | update_quadrature_points;
}

template <int dim>
void StressPostprocessor<dim>::evaluate_vector_field(
    const DataPostprocessorInputs::Vector<dim>& inputs,
    std::vector<Vector<double>>& computed_quantities) const
{
  const Material& material = *materials.at(inputs.template get_cell<dim>()->material_id());
  for (unsigned int q = 0; q < computed_quantities.size(); ++q)
  {
    Tensor<2, dim> displacement_gradient;
    Tensor<1, dim> displacement;
    for (unsigned int d = 0; d < dim; ++d)
    {
      displacement[d]          = inputs.solution_values[q][d];
      displacement_gradient[d] = inputs.solution_gradients[q][d];
    }
    evaluate(material,
             kinematics.deformation_gradient(
                 displacement_gradient, displacement, inputs.evaluation_points[q]),
             computed_quantities[q]);
  }
}

template <int dim>
void StressPostprocessor<dim>::evaluate_scalar_field(
    const DataPostprocessorInputs::Scalar<dim>& inputs,
    std::vector<Vector<double>>& computed_quantities) const
{
  AssertThrow(dim == 1, ExcMessage("A displacement field has dim components."));
  const Material& material = *materials.at(inputs.template get_cell<dim>()->material_id());
  for (unsigned int q = 0; q < computed_quantities.size(); ++q)
  {
    Tensor<2, dim> displacement_gradient;
    Tensor<1, dim> displacement;
    displacement[0]          = inputs.solution_values[q];
    displacement_gradient[0] = inputs.solution_gradients[q];
    evaluate(material,
             kinematics.deformation_gradient(
                 displacement_gradient, displacement, inputs.evaluation_points[q]),
             computed_quantities[q]);
  }
}

template <int dim>
void StressPostprocessor<dim>::evaluate(const Material& material,
                                        const Tensor<2, 3>& F,
                                        Vector<double>& out) const
{
  const Tensor<2, 3> sigma =
      material.first_piola_kirchhoff_stress(F) * transpose(F) / determinant(F);
  const Tensor<2, 3> strain     = 0.5 * (transpose(F) * F - unit_symmetric_tensor<3>());
  const SymmetricTensor<2, 3> s = deviator(symmetrize(sigma));
  const unsigned int n          = components.size();
  for (unsigned int c = 0; c < n; ++c)
  {
    out[c]     = sigma[components[c].first][components[c].second];
    out[n + c] = strain[components[c].first][components[c].second];
  }
  out[2 * n] = std::sqrt(1.5 * scalar_product(s, s));
}

DYNCONTACT_INSTANTIATE_CLASS(StressPostprocessor)
} // namespace dyncontact
