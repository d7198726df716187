#include <dyncontact/base/dimensions.h>
#include <dyncontact/models/problem_model.h>

namespace dyncontact
{
template <int dim>
std::vector<types::global_dof_index> ProblemModel<dim>::fixed_dofs(const NodeIndex<dim>&) const
{
  return {};
}

template <int dim>
std::vector<FixedBoundary> ProblemModel<dim>::fixed_boundaries() const
{
  return {};
}

template <int dim>
void ProblemModel<dim>::attach_manifolds(Triangulation<dim>&) const
{
}

template <int dim>
std::vector<SurfaceTraction<dim>> ProblemModel<dim>::surface_tractions() const
{
  return {};
}

template <int dim>
std::vector<BodyForce<dim>> ProblemModel<dim>::body_forces() const
{
  return {};
}

template <int dim>
void ProblemModel<dim>::write_reference(const std::string&,
                                        const std::vector<double>&,
                                        const std::vector<Node<dim>>&) const
{
}

template <int dim>
void ProblemModel<dim>::summarize_run(const std::string&,
                                      const History&,
                                      const std::vector<double>&,
                                      const std::string&,
                                      std::ostream&) const
{
}

DYNCONTACT_INSTANTIATE_CLASS(ProblemModel)
} // namespace dyncontact
