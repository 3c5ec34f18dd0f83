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

namespace
{
  /** Secondary node at (x, 1). */
  template <int dim>
  unsigned int
  secondary_node_at(const Patch<dim> &patch, const double x)
  {
    const auto &surface = patch.contact_problem->coupling().secondary_surface();
    for (unsigned int j = 0; j < surface.n_nodes(); ++j)
      if (std::abs(surface.node(j).position[0] - x) < 1e-10)
        return j;
    AssertThrow(false, ExcMessage("No secondary node at this x."));
    return 0;
  }

  void
  run(const unsigned int                 degree,
      const Common::Contact::FrictionLaw friction_law,
      const std::vector<std::pair<double, std::vector<unsigned int>>> &fixed)
  {
    Patch<2> patch(degree, plane_strain_stack, friction_law, 0.3);
    AffineConstraints<double> base;
    patch.make_grid_and_dofs(base);
    patch.add_lower_support(base);
    patch.add_symmetry(base);
    base.close();
    patch.setup_problem(base);

    // The same constraints and, in addition, the fixed components of the
    // chosen secondary nodes.
    AffineConstraints<double> constraints;
    constraints.reinit(complete_index_set(patch.dof_handler.n_dofs()));
    std::vector<unsigned int> nodes;
    for (const auto &[x, components] : fixed)
      {
        const unsigned int j = secondary_node_at(patch, x);
        nodes.push_back(j);
        const auto &dofs =
          patch.contact_problem->coupling().secondary_surface().node(j).dofs;
        for (const unsigned int c : components)
          constraints.add_line(dofs[c]);
      }
    constraints.merge(base, AffineConstraints<double>::left_object_wins, true);
    constraints.close();
    patch.setup_problem(constraints);

    const auto &enforcement = patch.contact_problem->enforcement();
    const auto &coupling    = patch.contact_problem->coupling();
    AffineConstraints<double> with_contact;
    with_contact.reinit(complete_index_set(patch.dof_handler.n_dofs()));
    with_contact.merge(constraints);
    enforcement.add_constraints(with_contact,
                                patch.contact_problem->displacement());
    with_contact.close();

    const auto &lagrange =
      dynamic_cast<const Common::Contact::DualLagrangeEnforcement<2> &>(
        enforcement.normal_enforcement());
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        const unsigned int j    = nodes[i];
        const auto        &dofs = coupling.secondary_surface().node(j).dofs;
        deallog << "node x = " << fixed[i].first << ": "
                << Common::Contact::to_string(enforcement.status(j));
        if (fixed[i].second.size() == 1)
          {
            // u_x: constrained by contact to the primary's mean motion?
            const auto *entries = with_contact.get_constraint_entries(dofs[0]);
            double      sum     = 0.;
            if (entries)
              for (const auto &entry : *entries)
                sum += entry.second;
            deallog << ", u_x held by contact: "
                    << yes_no(entries != nullptr && !entries->empty() &&
                              std::abs(sum - 1.) < 1e-12);
          }
        deallog << std::endl;
      }
    deallog << "sticking without normal row: "
            << lagrange.diagnostics().n_stick_without_normal
            << ", closed without constraint: "
            << lagrange.diagnostics().n_unconstrained << std::endl;

    const auto statistics = patch.solve_and_commit();
    deallog << "converged: " << yes_no(statistics.converged) << std::endl;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  attach_log();

  for (const unsigned int degree : {1u, 2u})
    {
      deallog << "Q" << degree << ", frictionless, u_y fixed at x = 0.5"
              << std::endl;
      run(degree, Common::Contact::FrictionLaw::frictionless, {{0.5, {1u}}});
      deallog << "Q" << degree
              << ", Coulomb, u_y fixed at x = 0.5, u fixed at x = 0.25"
              << std::endl;
      run(degree,
          Common::Contact::FrictionLaw::coulomb,
          {{0.5, {1u}}, {0.25, {0u, 1u}}});
    }
}
