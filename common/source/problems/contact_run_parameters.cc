#include <common/problems/contact_run_parameters.h>

#include <sstream>

namespace Common
{
  namespace Problems
  {
    using namespace dealii;

    void
    ContactRunParameters::declare_parameters(
      ParameterHandler                        &prm,
      const std::vector<Solvers::LoadChannel> &channels,
      const std::map<std::string, double>     &default_end_values)
    {
      Physics::SolidParameters::declare_parameters(prm);
      Contact::ContactParameters::declare_parameters(prm);
      Solvers::NonlinearSolverParameters::declare_parameters(prm);
      Solvers::LinearSolverParameters::declare_parameters(prm);
      Solvers::LoadProgramParameters::declare_parameters(prm,
                                                         channels,
                                                         default_end_values);
      IO::OutputParameters::declare_parameters(prm);
      IO::RunControlParameters::declare_parameters(prm);
    }



    void
    ContactRunParameters::parse_parameters(
      ParameterHandler                        &prm,
      const std::vector<Solvers::LoadChannel> &channels)
    {
      solid.parse_parameters(prm);
      contact.parse_parameters(prm);
      // Checks the contact configuration against the kinematics.
      contact.in_current_configuration(solid.finite_strain());
      nonlinear_solver.parse_parameters(prm);
      linear_solver.parse_parameters(prm);
      load_program.channels = channels;
      load_program.parse_parameters(prm);
      output.parse_parameters(prm);
      run_control.parse_parameters(prm);
      // Only friction that acts (Coulomb with mu > 0) makes the system
      // non-symmetric; 'coulomb' with mu = 0 is frictionless.
      const bool with_friction =
        contact.friction_law == Contact::FrictionLaw::coulomb &&
        contact.friction_coefficient > 0.;
      AssertThrow(!(linear_solver.type == Solvers::LinearSolverType::cg_amg &&
                    with_friction),
                  ExcMessage(
                    "Linear solver 'cg amg' needs a symmetric system, which "
                    "friction does not give; use 'gmres amg' or a direct "
                    "solver."));

      std::ostringstream text;
      prm.print_parameters(text, ParameterHandler::ShortPRM);
      used_parameters = text.str();
    }
  } // namespace Problems
} // namespace Common
