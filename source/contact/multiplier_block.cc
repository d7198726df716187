#include <dyncontact/contact/multiplier_block.h>

namespace dyncontact
{
MultiplierBlock::MultiplierBlock(const std::vector<unsigned int>& components_per_pair)
{
  for (const unsigned int components : components_per_pair)
  {
    AssertThrow(components >= 1, ExcMessage("a contact pair needs at least one multiplier"));
    first.push_back(first.back() + components);
  }
}
} // namespace dyncontact
