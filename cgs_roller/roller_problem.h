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
#include <common/problems/contact_application.h>
#include <common/solvers/load_program.h>

#include "parameters.h"

#include <string>
#include <vector>

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
   * Half model of a cylinder on a block, plane strain, small strain, mortar
   * contact, frictionless or with Coulomb friction.
   */
  class RollerProblem : public Common::Problems::ContactApplication<2>
  {
  public:
    static constexpr int dim = 2;

    explicit RollerProblem(const Parameters &parameters);

  private:
    std::string
    title() const override;
    void
    make_grid() override;
    void
    setup_system() override;
    Common::Problems::ExternalLoad
    external_load() const override;
    std::vector<std::string>
    result_files() const override;
    void
    postprocess_step(
      const Common::Solvers::StepInfo         &step,
      const Common::Solvers::NewtonStatistics &statistics) override;
    void
    output_results(
      const Common::Solvers::LoadSteppingStatistics &stepping) override;

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

    const Parameters &parameters;
    /** The vertical DoF of the roller's top vertex, where the force acts. */
    types::global_dof_index load_dof;
  };
} // namespace CgsRoller

#endif
