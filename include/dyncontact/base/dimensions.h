#pragma once

/**
 * The one list of space dimensions the dimension templates are compiled for: 1 (bars), 2
 * (axisymmetric bodies) and 3. A source file instantiates each of its class templates with
 * DYNCONTACT_INSTANTIATE_CLASS(Name), and a function template through a macro of `dim` passed to
 * DYNCONTACT_FOR_EACH_DIMENSION. (Node-to-segment contact is the one class without 1D: its face
 * patch is a 3-node line or a 9-node quadrilateral.)
 */
#define DYNCONTACT_FOR_EACH_DIMENSION(INSTANTIATE) INSTANTIATE(1) INSTANTIATE(2) INSTANTIATE(3)

/** Explicit instantiations of the class template `Name` for every dimension of the list. */
#define DYNCONTACT_INSTANTIATE_CLASS(Name)                                                         \
  template class Name<1>;                                                                          \
  template class Name<2>;                                                                          \
  template class Name<3>;
