#include <common/contact/normal_contact_law.h>

#include <algorithm>

namespace Common
{
  namespace Contact
  {
    namespace NormalContactLaw
    {
      bool
      is_active(const double pressure, const double gap, const double c)
      {
        return pressure - c * gap > 0.;
      }



      double
      complementarity(const double pressure, const double gap, const double c)
      {
        return pressure - std::max(0., pressure - c * gap);
      }



      double
      penalty_pressure(const double gap, const double stiffness)
      {
        return stiffness * std::max(0., -gap);
      }



      double
      penalty_derivative(const double gap, const double stiffness)
      {
        return (gap <= 0. ? -stiffness : 0.);
      }
    } // namespace NormalContactLaw
  }   // namespace Contact
} // namespace Common
