/*
 * The check of the shared parameter blocks (ContactRunParameters) that
 * keeps the conjugate gradient solver 'cg amg' from a non-symmetric
 * system: it must reject 'cg amg' only where friction makes the system
 * non-symmetric, i.e. Coulomb friction with mu > 0, and accept it without
 * friction and for 'coulomb' with mu = 0 (no tangential traction, a
 * symmetric system). 'gmres amg' and the direct solvers are accepted with
 * friction. Each case prints "accepted" or the first line of the error.
 */

#include <common/problems/contact_run_parameters.h>

#include "../tests.h"

#include <deal.II/base/parameter_handler.h>

#include <sstream>
#include <string>

using namespace dealii;

namespace
{
  void
  check(const std::string &friction_law,
        const double       mu,
        const std::string &solver)
  {
    ParameterHandler prm;
    Common::Problems::ContactRunParameters::declare_parameters(prm);
    std::ostringstream input;
    input << "subsection Contact\n"
          << "  set Friction law         = " << friction_law << "\n"
          << "  set Friction coefficient = " << mu << "\n"
          << "end\n"
          << "subsection Linear solver\n"
          << "  set Solver type = " << solver << "\n"
          << "end\n";
    prm.parse_input_from_string(input.str());
    std::string result = "accepted";
    try
      {
        Common::Problems::ContactRunParameters parameters;
        parameters.parse_parameters(prm);
      }
    catch (const ExceptionBase &e)
      {
        const std::string what = e.what();
        result                 = std::string("rejected") +
                 (what.find("needs a symmetric system") != std::string::npos ?
                    " (needs a symmetric system)" :
                    " (other error)");
      }
    deallog << friction_law << ", mu = " << mu << ", " << solver << ": "
            << result << std::endl;
  }
} // namespace



int
main()
{
  initlog();
  check("frictionless", 0., "cg amg");
  check("coulomb", 0., "cg amg");
  check("coulomb", 0.1, "cg amg");
  check("coulomb", 0.1, "gmres amg");
  check("coulomb", 0.1, "mumps");
  check("frictionless", 0., "gmres amg");
}
