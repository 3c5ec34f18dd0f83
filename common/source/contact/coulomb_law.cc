#include <common/contact/coulomb_law.h>

#include <deal.II/base/symmetric_tensor.h>

#include <algorithm>

namespace Common
{
  namespace Contact
  {
    namespace CoulombLaw
    {
      using namespace dealii;

      template <int dim>
      Tensor<1, dim>
      project_onto_disc(const Tensor<1, dim> &x, const double radius)
      {
        const double norm = x.norm();
        if (norm <= radius)
          return x;
        return (radius / norm) * x;
      }



      template <int dim>
      Tensor<1, dim>
      complementarity(const Tensor<1, dim> &traction,
                      const Tensor<1, dim> &slip_increment,
                      const double          slip_bound,
                      const double          c)
      {
        return traction - project_onto_disc(traction + c * slip_increment,
                                            std::max(0., slip_bound));
      }



      template <int dim>
      bool
      is_sticking(const Tensor<1, dim> &traction,
                  const Tensor<1, dim> &slip_increment,
                  const double          slip_bound,
                  const double          c)
      {
        return (traction + c * slip_increment).norm() <=
               std::max(0., slip_bound);
      }



      template <int dim>
      Tensor<1, dim>
      slip_direction(const Tensor<1, dim> &traction,
                     const Tensor<1, dim> &slip_increment,
                     const double          c)
      {
        const Tensor<1, dim> trial = traction + c * slip_increment;
        const double         norm  = trial.norm();
        return (norm > 0. ? trial / norm : Tensor<1, dim>());
      }



      template <int dim>
      SlipLinearisation<dim>
      slip_linearisation(const Tensor<1, dim> &traction,
                         const Tensor<1, dim> &slip_increment,
                         const double          slip_bound,
                         const double          c)
      {
        SlipLinearisation<dim> result;
        const Tensor<1, dim>   trial = traction + c * slip_increment;
        const double           norm  = trial.norm();
        const double           s     = std::max(0., slip_bound);
        if (norm > 0.)
          result.direction = trial / norm;
        if (norm > s)
          result.turning_stiffness = c * s / (norm - s);
        return result;
      }



      template <int dim>
      Jacobian<dim>
      complementarity_jacobian(const Tensor<1, dim> &traction,
                               const Tensor<1, dim> &slip_increment,
                               const double          slip_bound,
                               const double          c)
      {
        const Tensor<2, dim> identity(unit_symmetric_tensor<dim>());
        Jacobian<dim>        jacobian;
        if (is_sticking(traction, slip_increment, slip_bound, c))
          {
            jacobian.d_slip_increment = -c * identity;
            return jacobian;
          }
        const Tensor<1, dim> trial = traction + c * slip_increment;
        const double         norm  = trial.norm();
        const Tensor<1, dim> e     = trial / norm;
        const Tensor<2, dim> curvature =
          (std::max(0., slip_bound) / norm) * (identity - outer_product(e, e));
        jacobian.d_traction       = identity - curvature;
        jacobian.d_slip_increment = -c * curvature;
        jacobian.d_slip_bound     = -e;
        return jacobian;
      }

#define INSTANTIATE(dim)                                                     \
  template Tensor<1, dim>         project_onto_disc(const Tensor<1, dim> &,  \
                                                    const double);           \
  template Tensor<1, dim>         complementarity(const Tensor<1, dim> &,    \
                                                  const Tensor<1, dim> &,    \
                                                  const double,              \
                                                  const double);             \
  template bool                   is_sticking(const Tensor<1, dim> &,        \
                                              const Tensor<1, dim> &,        \
                                              const double,                  \
                                              const double);                 \
  template Tensor<1, dim>         slip_direction(const Tensor<1, dim> &,     \
                                                 const Tensor<1, dim> &,     \
                                                 const double);              \
  template SlipLinearisation<dim> slip_linearisation(const Tensor<1, dim> &, \
                                                     const Tensor<1, dim> &, \
                                                     const double,           \
                                                     const double);          \
  template Jacobian<dim> complementarity_jacobian(const Tensor<1, dim> &,    \
                                                  const Tensor<1, dim> &,    \
                                                  const double,              \
                                                  const double);
      INSTANTIATE(2)
      INSTANTIATE(3)
#undef INSTANTIATE
    } // namespace CoulombLaw
  }   // namespace Contact
} // namespace Common
