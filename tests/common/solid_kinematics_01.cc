/*
 * The kinematics of a scene chosen in its parameter file (subsection
 * Solid, "Kinematics = small strain | finite strain"), through the solid
 * operator factory and the contact-Newton core. The two-block patch
 * (tests/two_block_patch.h, plane strain, Q2, non-matching meshes): the
 * lower block E = 70000 MPa, nu = 0.3, the upper one E = 210000 MPa,
 * nu = 0.1, so that the two faces want to expand differently and Coulomb
 * friction (mu = 0.3) makes the interface shear non-uniform; a pressure p
 * on the top.
 *
 * (a) Elastic case at strains of about 1e-5 (p = 0.7 MPa): the
 *     finite-strain run (compressible neo-Hookean laws with the same E
 *     and nu) agrees with the small-strain run to 1e-4: the largest
 *     displacement difference relative to the largest displacement, and
 *     the largest difference of the nodal contact pressures relative to
 *     p. At p = 70 MPa (strains about 1e-3) the difference is printed: it
 *     must grow like the strain (ratio between 30 and 300 for 100 times
 *     the load), which shows that it is the kinematics and not a defect.
 * (b) The upper block exactly incompressible (neo-Hookean split,
 *     nu = 0.5, mixed Q2-P1 element): the core repeats the Newton solve
 *     after each multiplier update until the projected J of every cell of
 *     the upper block is within 1e-8 of 1; the updates are counted and the
 *     force balance holds (contact force = p L within 1e-8).
 * (c) Bad input gets a one-line message naming the body and the entry:
 *     J2 plasticity under small strain; nu = 0.5 under small strain; nu =
 *     0.5 with the displacement element; F-bar on Q2.
 */

#include <common/contact/contact_postprocessor.h>
#include <common/io/run_main.h>
#include <common/physics/finite_strain_solid.h>
#include <common/physics/solid_model.h>

#include "../tests.h"
#include "two_block_patch.h"

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace dealii;
using namespace TwoBlockPatch;

namespace
{
  const Setting setting{70000., 210000., 0.3, 1., 1.};

  /** The solid parameters and the materials of both blocks, parsed from
   * @p text. */
  struct SolidInput
  {
    explicit SolidInput(const std::string &text)
    {
      ParameterHandler prm;
      Common::Physics::SolidParameters::declare_parameters(prm);
      Common::Materials::SolidMaterialParameters::declare_parameters(
        prm,
        "Lower material");
      Common::Materials::SolidMaterialParameters::declare_parameters(
        prm,
        "Upper material");
      prm.parse_input_from_string(text);
      solid.parse_parameters(prm);
      lower.parse_parameters(prm, "Lower material", solid.finite_strain());
      upper.parse_parameters(prm, "Upper material", solid.finite_strain());
    }

    Common::Physics::SolidParameters           solid;
    Common::Materials::SolidMaterialParameters lower;
    Common::Materials::SolidMaterialParameters upper;
  };

  std::string
  input(const std::string &kinematics,
        const std::string &upper_model = "neo-Hookean",
        const double       upper_nu    = 0.1,
        const std::string &technology  = "displacement",
        const std::string &lower_model = "neo-Hookean",
        const double       lower_nu    = 0.3)
  {
    return "subsection Solid\n  set Kinematics = " + kinematics +
           "\n  set Element technology = " + technology +
           "\nend\nsubsection Lower material\n  set Young's modulus = 70000"
           "\n  set Poisson's ratio = " +
           std::to_string(lower_nu) +
           "\n  set Finite strain model = " + lower_model +
           "\nend\nsubsection Upper material\n  set Young's modulus = "
           "210000\n  set Poisson's ratio = " +
           std::to_string(upper_nu) +
           "\n  set Finite strain model = " + upper_model + "\nend\n";
  }

  struct Result
  {
    Vector<double>                    displacement;
    std::vector<double>               pressures;
    Common::Solvers::NewtonStatistics statistics;
    double                            contact_force      = 0.;
    double                            largest_dilatation = 0.;
  };

  Result
  solve(const std::string &text, const double pressure)
  {
    Setting s  = setting;
    s.pressure = pressure;
    Patch<2> patch(2, s, Common::Contact::FrictionLaw::coulomb, 0.3);
    AffineConstraints<double> constraints;
    patch.make_grid_and_dofs(constraints);
    patch.add_lower_support(constraints);
    patch.add_symmetry(constraints);
    constraints.close();
    const SolidInput in(text);
    patch.setup_problem(constraints,
                        Common::Physics::create_solid_operator<2>(
                          in.solid,
                          patch.mapping,
                          patch.fe,
                          {{MaterialIds::lower, in.lower},
                           {MaterialIds::upper, in.upper}}));

    Result result;
    result.statistics = patch.solve_and_commit();
    result.displacement.reinit(patch.dof_handler.n_dofs());
    const auto &u = patch.contact_problem->displacement();
    for (unsigned int i = 0; i < patch.dof_handler.n_dofs(); ++i)
      result.displacement(i) = u(i);

    const auto &enforcement = patch.contact_problem->enforcement();
    const auto &surface = patch.contact_problem->coupling().secondary_surface();
    for (unsigned int j = 0; j < surface.n_nodes(); ++j)
      result.pressures.push_back(enforcement.pressure(j));
    result.contact_force =
      -Common::Contact::total_contact_force(patch.contact_problem->coupling(),
                                            enforcement)[1];

    if (const auto *finite =
          dynamic_cast<const Common::Physics::FiniteStrainSolid<2> *>(
            &patch.contact_problem->solid()))
      for (const auto &cell : patch.dof_handler.active_cell_iterators())
        if (cell->material_id() == MaterialIds::upper)
          result.largest_dilatation =
            std::max(result.largest_dilatation,
                     std::abs(finite->cell_averages(cell->active_cell_index())
                                .projected_jacobian -
                              1.));
    return result;
  }

  /** Largest displacement difference over the largest displacement, and
   * largest pressure difference over p. */
  std::pair<double, double>
  difference(const Result &a, const Result &b, const double pressure)
  {
    Vector<double> d = a.displacement;
    d -= b.displacement;
    double dp = 0.;
    for (unsigned int j = 0; j < a.pressures.size(); ++j)
      dp = std::max(dp, std::abs(a.pressures[j] - b.pressures[j]));
    return {d.linfty_norm() / b.displacement.linfty_norm(), dp / pressure};
  }

  void
  check_agreement()
  {
    deallog << "(a) finite against small strain, elastic" << std::endl;
    std::vector<double> displacement_differences;
    for (const double pressure : {0.7, 70.})
      {
        const Result small  = solve(input("small strain"), pressure);
        const Result large  = solve(input("finite strain"), pressure);
        const auto [du, dp] = difference(large, small, pressure);
        displacement_differences.push_back(du);
        deallog << "p = " << pressure << " MPa (strain about "
                << format(pressure / 70000., 2)
                << "): Newton iterations small/finite "
                << small.statistics.n_iterations << "/"
                << large.statistics.n_iterations << ", displacement difference "
                << format(du, 2) << ", pressure difference " << format(dp, 2)
                << std::endl;
        if (pressure < 1.)
          deallog << "  agreement to 1e-4: "
                  << pass_fail(small.statistics.converged &&
                               large.statistics.converged && du < 1e-4 &&
                               dp < 1e-4)
                  << std::endl;
      }
    const double growth =
      displacement_differences[1] / displacement_differences[0];
    deallog << "difference grows with the strain (100 x load): ratio "
            << format(growth, 3) << " "
            << pass_fail(growth > 30. && growth < 300.) << std::endl;
  }

  void
  check_incompressible()
  {
    deallog << "(b) upper block exactly incompressible, mixed Q2-P1"
            << std::endl;
    const double pressure = 100.;
    const Result result   = solve(input("finite strain",
                                      "neo-Hookean split",
                                      0.5,
                                      "mixed",
                                      "neo-Hookean split",
                                      0.3),
                                pressure);
    const double balance =
      std::abs(result.contact_force - pressure * interface_length) /
      (pressure * interface_length);
    deallog << "converged: " << yes_no(result.statistics.converged)
            << ", multiplier updates: "
            << (result.statistics.n_augmentations > 0 ? "yes" : "no")
            << ", largest |projected J - 1| below 1e-8: "
            << pass_fail(result.largest_dilatation < 1e-8)
            << ", force balance within 1e-8: " << pass_fail(balance < 1e-8)
            << std::endl;
  }

  void
  check_bad_input()
  {
    deallog << "(c) bad input" << std::endl;
    const std::vector<std::string> cases = {
      input("small strain", "J2 plasticity"),
      input("small strain", "neo-Hookean split", 0.5),
      input("finite strain", "neo-Hookean split", 0.5),
      input("finite strain", "neo-Hookean", 0.1, "F-bar")};
    for (const auto &text : cases)
      try
        {
          const Result result = solve(text, 1.);
          deallog << "accepted: FAIL" << std::endl;
        }
      catch (const ExceptionBase &e)
        {
          deallog << Common::IO::one_line_message(e) << std::endl;
        }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  deallog << std::setprecision(6);
  check_agreement();
  check_incompressible();
  check_bad_input();
}
