#include <common/materials/solid_material.h>

namespace Common
{
  namespace Materials
  {
    using namespace dealii;

    void
    SolidMaterialParameters::declare_parameters(ParameterHandler  &prm,
                                                const std::string &subsection)
    {
      LinearElasticParameters::declare_parameters(prm, subsection);
      FiniteStrainMaterialParameters::declare_parameters(prm, subsection);
    }



    void
    SolidMaterialParameters::parse_parameters(ParameterHandler  &prm,
                                              const std::string &subsection,
                                              const bool         finite)
    {
      name = subsection;
      if (finite)
        {
          finite_strain.parse_parameters(prm, subsection);
          youngs_modulus                = finite_strain.youngs_modulus;
          poisson_ratio                 = finite_strain.poisson_ratio;
          linear_elastic.youngs_modulus = youngs_modulus;
          linear_elastic.poisson_ratio  = poisson_ratio;
        }
      else
        {
          prm.enter_subsection(subsection);
          const double nu = prm.get_double("Poisson's ratio");
          prm.leave_subsection();
          AssertThrow(nu < 0.5,
                      ExcMessage(subsection +
                                 ": Poisson's ratio must lie in (-1, 0.5), "
                                 "got " +
                                 std::to_string(nu) +
                                 ": an incompressible body needs "
                                 "'Kinematics = finite strain' in "
                                 "subsection Solid."));
          linear_elastic.parse_parameters(prm, subsection);
          youngs_modulus = linear_elastic.youngs_modulus;
          poisson_ratio  = linear_elastic.poisson_ratio;
          prm.enter_subsection(subsection);
          const std::string model = prm.get("Finite strain model");
          prm.leave_subsection();
          AssertThrow(model != "J2 plasticity",
                      ExcMessage(subsection +
                                 ": 'Finite strain model = J2 plasticity' "
                                 "needs 'Kinematics = finite strain' in "
                                 "subsection Solid."));
        }
    }
  } // namespace Materials
} // namespace Common
