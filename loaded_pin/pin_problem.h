/*
 * Benchmark 4 of the FENET/NAFEMS advanced contact benchmarks, "3D loaded
 * pin": a steel pin in the hole of an aluminium lug, pulled along the lug
 * by point forces at the centres of its end faces; the quarter model
 * y >= 0, z >= 0. Receding contact: the pin fits the hole without
 * clearance, and under load the contact arc shrinks to the side the pin
 * bears on.
 */
#ifndef loaded_pin_pin_problem_h
#define loaded_pin_pin_problem_h

#include <common/contact/contact_postprocessor.h>
#include <common/problems/contact_application.h>

#include "parameters.h"

#include <string>
#include <vector>

namespace LoadedPin
{
  using namespace dealii;

  /**
   * @brief The contact result at one hole node, in the benchmark's terms.
   */
  struct PinContactPoint
  {
    /** Angle at the hole axis from the point facing the clamp, 180 degrees
     * minus atan2(y, x) (degrees). */
    double theta;
    /** Reference position (mm). */
    Point<3> position;
    /** Contact pressure, positive in compression (MPa). */
    double pressure;
    /** Circumferential traction the sheet exerts on the pin, along
     * e_theta = (sin phi, -cos phi, 0), phi = atan2(y, x) (MPa). */
    double q_theta;
    /** Axial traction the sheet exerts on the pin (MPa). */
    double q_z;
    /** Circumferential relative displacement, pin minus sheet, along
     * e_theta, since the unloaded state (mm). */
    double slip_theta;
    /** Circumferential slip accumulated in contact, pin minus sheet
     * (mm). */
    double accumulated_slip_theta;
    /** Mean normal gap (mm). */
    double gap;
    /** "open", "stick" or "slip". */
    std::string status;
  };

  /**
   * @brief The contact results along one line of the hole z = const,
   * sorted by decreasing theta (from the bearing point theta = 180
   * degrees).
   */
  struct PinContactLine
  {
    /** The plane z of the line (mm). */
    double                       z;
    std::vector<PinContactPoint> points;
    /** Peak pressure (MPa) and its theta (degrees): the largest nodal
     * value. */
    double peak_pressure = 0., peak_pressure_theta = 0.;
    /** Peak pressure (MPa) and its theta (degrees) of the parabola through
     * the largest nodal value and its two neighbours: the peak between the
     * nodes, less dependent on where the nodes fall. */
    double fitted_peak_pressure = 0., fitted_peak_pressure_theta = 0.;
    /** End of the contact arc theta_c (degrees): the arc is
     * theta_c <= theta <= 180. */
    double arc_end_theta = 180.;
    /** Largest |q_theta| (MPa) and its theta (degrees). */
    double peak_traction = 0., peak_traction_theta = 0.;
    /** Largest |slip_theta| (mm). */
    double max_slip = 0.;
    /** End of the stick zone that starts at the bearing point (degrees);
     * 180 if the bearing point slips. */
    double stick_end_theta = 180.;
  };

  /**
   * @brief The loaded pin, small strain, mortar contact between the hole
   * (secondary) and the pin (primary), with optional Coulomb friction.
   */
  class PinProblem : public Common::Problems::ContactApplication<3>
  {
  public:
    explicit PinProblem(const Parameters &parameters);

  private:
    static constexpr int dim = 3;
    using Base               = Common::Problems::ContactApplication<dim>;

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

    /** The contact results on the hole line z = @p z (mm). */
    PinContactLine
    contact_line(const double z) const;

    /** The x component of the displacement at the DoF @p dof (mm),
     * collected from its owner. */
    double
    displacement_at(const types::global_dof_index dof) const;

    /** The x resultant of the contact tractions on the sheet, quarter
     * model (N). */
    double
    contact_resultant() const;

    /** The force on the quarter model at the load factor (N). */
    double
    applied_force(const double load_factor) const;

    const Parameters &parameters;
    /** The x DoF of the pin's end-face centre (0, 0, L2/2), loaded. */
    types::global_dof_index load_dof;
    /** The x DoFs of the pin centre (0, 0, 0), the sheet's bearing point
     * (R1, 0, 0) and its tip (R2, 0, 0). */
    types::global_dof_index pin_centre_dof, bearing_point_dof, lug_tip_dof;
  };
} // namespace LoadedPin

#endif
