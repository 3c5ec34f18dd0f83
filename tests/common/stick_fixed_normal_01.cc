/*
 * A sticking secondary node whose normal displacement a Dirichlet
 * condition fixes: the plane-strain two-block patch (Q1 and Q2, lower
 * block supported at its bottom, symmetry line x = 0, Coulomb friction
 * mu = 0.3) with the vertical displacement of the secondary node at
 * x = 0.5 fixed as well (a support under the contact surface). Every
 * touching node starts closed and sticking. The node's normal condition
 * cannot act on its only free component u_x, so the square system of its
 * normal and tangential rows is singular; its stick condition must not be
 * lost with it: u_x must be constrained by contact to the mean horizontal
 * motion of the primary partners (weights summing to 1), and the node is
 * counted as sticking without its normal row (and reported once on
 * stderr). Its normal condition is the support's: its normal
 * complementarity does not count, and the Newton iteration converges at
 * full load.
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
      deallog << "Q" << degree << ", Coulomb, u_y fixed at x = 0.5"
              << std::endl;
      run_with_fixed_secondary_nodes(degree,
                                     Common::Contact::FrictionLaw::coulomb,
                                     {{0.5, {1u}}},
                                     false);
    }
}
