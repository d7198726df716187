#include <dyncontact/problem_model.h>

namespace dyncontact
{
template <int dim>
void ProblemModel<dim>::write_reference(const std::string&,
                                        const std::vector<double>&,
                                        const std::vector<Node<dim>>&) const
{
}

template class ProblemModel<1>;
template class ProblemModel<2>;
} // namespace dyncontact
