/*
 * The cgs_roller problem: geometry, boundary conditions and loading of
 * benchmark 1, wired to the contact, material and solver components of the
 * common library. No contact or material algorithm lives here.
 */
#ifndef cgs_roller_roller_problem_h
#define cgs_roller_roller_problem_h

#include <common/analytic/hertz.h>
#include <common/analytic/spence.h>
#include <common/contact/contact_postprocessor.h>
#include <common/io/console.h>
#include <common/io/json_writer.h>
#include <common/physics/small_strain_elasticity.h>
#include <common/problems/small_strain_contact_problem.h>
#include <common/solvers/load_stepping.h>

#include "parameters.h"

#include <deal.II/base/index_set.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/affine_constraints.h>

#include <memory>

namespace CgsRoller
{
  using namespace dealii;

  /** Boundary ids of the two bodies (see README.md). */
  namespace BoundaryIds
  {
    constexpr types::boundary_id block_bottom    = 1;
    constexpr types::boundary_id block_top       = 2;
    constexpr types::boundary_id block_symmetry  = 3;
    constexpr types::boundary_id block_side      = 4;
    constexpr types::boundary_id roller_surface  = 5;
    constexpr types::boundary_id roller_symmetry = 6;
  } // namespace BoundaryIds

  /** Material ids: one per body. */
  namespace MaterialIds
  {
    constexpr types::material_id roller = 1;
    constexpr types::material_id block  = 2;
  } // namespace MaterialIds

  /**
   * Half model of a cylinder on a block, plane strain, small strain,
   * frictionless mortar contact.
   */
  template <int dim>
  class RollerProblem
  {
  public:
    explicit RollerProblem(const Parameters &parameters);

    /** Build, solve all load steps and write the results. */
    void
    run();

  private:
    void
    make_grid();
    void
    setup_system();
    Common::Problems::ExternalLoad
    external_load() const;
    /** Spence's partial-slip solution at full load (mu = 0 allowed). */
    Common::Analytic::SpencePartialSlip
    spence_reference() const;
    /** Contact results at a load factor, with the Hertz reference. */
    struct Results
    {
      Common::Analytic::HertzLineContact                    hertz;
      std::vector<Common::Contact::ContactPointResult<dim>> profile;
      double peak_pressure;            // MPa
      double half_width;               // mm
      double contact_force;            // N/mm, half model, compressive positive
      double applied_force;            // N/mm, half model
      double stick_half_width;         // mm
      double peak_tangential_traction; // MPa, largest |t|
      double slip_at_half_contact;     // mm, accumulated slip at x = a/2
    };
    Results
    evaluate_results(const double load_factor) const;
    void
    postprocess_step(const unsigned int                       step,
                     const double                             load_factor,
                     const Common::Solvers::NewtonStatistics &statistics);
    void
    output_results(const Common::Solvers::LoadSteppingStatistics &stepping);

    // Run set-up
    const Parameters   &parameters;
    MPI_Comm            mpi_communicator;
    Common::IO::Console console;

    // Discretisation
    parallel::shared::Triangulation<dim>                         triangulation;
    const FESystem<dim>                                          fe;
    const MappingQ<dim>                                          mapping;
    DoFHandler<dim>                                              dof_handler;
    types::global_dof_index                                      load_dof;
    std::unique_ptr<Common::Physics::SmallStrainElasticity<dim>> physics;

    // Contact problem and its state
    AffineConstraints<double> constraints_dirichlet_and_hanging_nodes;
    std::unique_ptr<Common::Problems::SmallStrainContactProblem<dim>>
      contact_problem;

    // Results
    Common::IO::JsonObject timings;
  };
} // namespace CgsRoller

#endif
