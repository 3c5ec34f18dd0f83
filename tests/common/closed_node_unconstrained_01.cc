/*
 * Closed secondary nodes on which no contact constraint can act must be
 * counted (and reported once on stderr), never dropped silently: the
 * plane-strain two-block patch (Q1 and Q2, lower block supported at its
 * bottom, symmetry line x = 0), every touching node closed at the start,
 * (a) frictionless, with the vertical displacement of the secondary node
 * at x = 0.5 fixed: the node slips, and its normal condition has no free
 * component to act on; (b) Coulomb friction mu = 0.3, with both
 * displacements of the node at x = 0.25 fixed (and u_y at x = 0.5, which
 * sticks and is held along its tangent, not counted here). Each case
 * counts one closed node without constraint, and the Newton iteration
 * then converges at full load.
 */

#include <common/contact/normal_enforcement.h>

#include "../tests.h"
#include "two_block_patch.h"

#include <deal.II/base/conditional_ostream.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

using namespace dealii;
using namespace TwoBlockPatch;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  attach_log();

  for (const unsigned int degree : {1u, 2u})
    {
      deallog << "Q" << degree << ", frictionless, u_y fixed at x = 0.5"
              << std::endl;
      run_with_fixed_secondary_nodes(degree,
                                     Common::Contact::FrictionLaw::frictionless,
                                     {{0.5, {1u}}},
                                     true);
      deallog << "Q" << degree
              << ", Coulomb, u_y fixed at x = 0.5, u fixed at x = 0.25"
              << std::endl;
      run_with_fixed_secondary_nodes(degree,
                                     Common::Contact::FrictionLaw::coulomb,
                                     {{0.5, {1u}}, {0.25, {0u, 1u}}},
                                     true);
    }
}
