#include <common/io/run_control.h>

namespace Common
{
  namespace IO
  {
    using namespace dealii;

    void
    RunControlParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Run control");
      {
        prm.declare_entry("Dry run",
                          "false",
                          Patterns::Bool(),
                          "Stop after building the mesh, the DoFs and the "
                          "contact pairing; print their sizes.");
        prm.declare_entry("Measure contact cost",
                          "false",
                          Patterns::Bool(),
                          "After the last step, time one assembly and linear "
                          "solve with the converged active set held fixed, "
                          "and report the ratio of the contact solve's time "
                          "to it (summary.json and console).");
      }
      prm.leave_subsection();
    }



    void
    RunControlParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Run control");
      {
        dry_run              = prm.get_bool("Dry run");
        measure_contact_cost = prm.get_bool("Measure contact cost");
      }
      prm.leave_subsection();
    }
  } // namespace IO
} // namespace Common
