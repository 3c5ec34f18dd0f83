// Checks the finite-strain material laws of Common::Materials at a point:
//
// 1. Uniaxial tension of J2 plasticity (E = 70500 MPa, nu = 0.342, the
//    sheet of benchmark 3) with each hardening law (linear, Swift, power
//    law with yield, tabulated), stretched to a logarithmic strain of 0.2
//    in 20 steps, the lateral stretch found by Newton's method so that the
//    lateral stresses vanish (1e-9 MPa): the axial Kirchhoff stress solves
//    tau = sigma_f(ln(lambda) - tau/E) (relative error < 1e-10), the
//    equivalent plastic strain is ln(lambda) - tau/E (1e-10) and the
//    lateral log strain is -nu tau/E - ep/2 (1e-10).
// 2. Release of that bar to zero axial stress: exactly elastic (the
//    plastic strain does not change, 1e-12), the stress returns to zero
//    (1e-8 MPa) and the permanent log strain equals the plastic strain
//    (1e-8).
// 3. The tangent d tau/d F of every law (elastic and plastic states, whole
//    and isochoric stress) against central differences of the stress
//    (step 1e-6): largest difference over largest entry < 1e-6.
// 4. Objectivity: a plastically stretched and sheared point turned by a
//    superposed rigid rotation in 36 steps of 10 degrees to 360 degrees,
//    each step committed: the Kirchhoff stress is Q tau Q^T and its
//    invariants do not change (1e-10 relative), no plastic strain
//    accumulates (1e-12).
// 5. Simple shear of the neo-Hookean laws against their closed forms:
//    tau_12 = mu gamma, tau_11 = mu gamma^2 (compressible) and
//    2/3 mu gamma^2 (split), 1e-12 relative.
// 6. Bad hardening parameters give one-line messages.

#include <common/materials/finite_strain_material.h>

#include "../tests.h"

#include <cmath>
#include <functional>
#include <iomanip>

using namespace dealii;
using namespace Common::Materials;

namespace
{
  Tensor<2, 3>
  diagonal(const double a, const double b, const double c)
  {
    Tensor<2, 3> F;
    F[0][0] = a;
    F[1][1] = b;
    F[2][2] = c;
    return F;
  }

  Tensor<2, 3>
  rotation(const double angle, const Tensor<1, 3> &axis_in)
  {
    const Tensor<1, 3> axis = axis_in / axis_in.norm();
    Tensor<2, 3>       Q;
    const double       c = std::cos(angle), s = std::sin(angle);
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        Q[i][j] = (i == j ? c : 0.) + (1. - c) * axis[i] * axis[j];
    Q[0][1] -= s * axis[2];
    Q[1][0] += s * axis[2];
    Q[0][2] += s * axis[1];
    Q[2][0] -= s * axis[1];
    Q[1][2] -= s * axis[0];
    Q[2][1] += s * axis[0];
    return Q;
  }

  HardeningParameters
  hardening(const HardeningType type)
  {
    HardeningParameters p;
    p.type                 = type;
    p.yield_stress         = 194.;
    p.hardening_modulus    = 1000.;
    p.strength_coefficient = 550.4;
    p.exponent             = 0.223;
    p.youngs_modulus       = 70500.;
    p.table = {{0., 194.}, {0.02, 230.}, {0.05, 260.}, {0.1, 290.}};
    return p;
  }

  /** Lateral stretch of a uniaxial stress state at axial stretch lambda. */
  double
  lateral_stretch(const FiniteStrainMaterial &law,
                  const MaterialPointState   &state,
                  const double                lambda,
                  double                      guess)
  {
    FiniteStrainResponse response;
    for (unsigned int it = 0; it < 50; ++it)
      {
        law.evaluate(diagonal(lambda, guess, guess),
                     state,
                     StressPart::full,
                     response);
        const double r = response.kirchhoff_stress[1][1];
        if (std::abs(r) < 1e-10)
          break;
        const double dr =
          response.tangent[1][1][1][1] + response.tangent[1][1][2][2];
        guess -= r / dr;
      }
    return guess;
  }

  /** Largest difference between the tangent and central differences,
   * over the largest tangent entry. */
  double
  tangent_error(const FiniteStrainMaterial &law,
                const Tensor<2, 3>         &F,
                const MaterialPointState   &state,
                const StressPart            part)
  {
    FiniteStrainResponse response, plus, minus;
    law.evaluate(F, state, part, response);
    const double h       = 1e-6;
    double       largest = 0., error = 0.;
    for (unsigned int k = 0; k < 3; ++k)
      for (unsigned int l = 0; l < 3; ++l)
        {
          Tensor<2, 3> Fp = F, Fm = F;
          Fp[k][l] += h;
          Fm[k][l] -= h;
          law.evaluate(Fp, state, part, plus);
          law.evaluate(Fm, state, part, minus);
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = 0; j < 3; ++j)
              {
                const double fd =
                  (plus.kirchhoff_stress[i][j] - minus.kirchhoff_stress[i][j]) /
                  (2. * h);
                largest =
                  std::max(largest, std::abs(response.tangent[i][j][k][l]));
                error =
                  std::max(error, std::abs(fd - response.tangent[i][j][k][l]));
              }
        }
    return error / largest;
  }
} // namespace



int
main()
{
  initlog();
  const double E = 70500., nu = 0.342;

  // 1, 2: uniaxial tension and release.
  const std::vector<std::pair<std::string, HardeningType>> laws = {
    {"linear", HardeningType::linear},
    {"Swift", HardeningType::swift},
    {"power law with yield", HardeningType::power_law_with_yield},
    {"tabulated", HardeningType::tabulated}};
  for (const auto &[name, type] : laws)
    {
      const J2Plasticity law(E, nu, hardening(type));
      MaterialPointState state;
      double lateral = 1., error_tau = 0., error_ep = 0., error_lateral = 0.;
      FiniteStrainResponse response;
      double               lambda = 1.;
      for (unsigned int step = 1; step <= 20; ++step)
        {
          lambda  = std::exp(0.01 * step);
          lateral = lateral_stretch(law, state, lambda, lateral);
          MaterialPointState updated;
          law.evaluate(diagonal(lambda, lateral, lateral),
                       state,
                       StressPart::full,
                       response,
                       &updated);
          state = updated;

          // Closed form: tau = sigma_f(ln lambda - tau/E) once yielding.
          const double eps = std::log(lambda);
          double       tau = E * eps;
          if (tau > law.hardening().initial_yield_stress())
            {
              double lo = 0., hi = E * eps;
              for (unsigned int it = 0; it < 200; ++it)
                {
                  const double mid = 0.5 * (lo + hi);
                  (mid - law.hardening().flow_stress(eps - mid / E) > 0. ? hi :
                                                                           lo) =
                    mid;
                }
              tau = 0.5 * (lo + hi);
            }
          const double ep = std::max(eps - tau / E, 0.);
          error_tau =
            std::max(error_tau,
                     std::abs(response.kirchhoff_stress[0][0] - tau) / tau);
          error_ep =
            std::max(error_ep, std::abs(state.equivalent_plastic_strain - ep));
          error_lateral =
            std::max(error_lateral,
                     std::abs(std::log(lateral) - (-nu * tau / E - ep / 2.)));
        }
      deallog << name << ": tau(0.2) = " << std::setprecision(4)
              << response.kirchhoff_stress[0][0]
              << " MPa, ep = " << std::setprecision(6)
              << state.equivalent_plastic_strain << std::endl;
      deallog << "  axial stress error < 1e-10: " << (error_tau < 1e-10)
              << ", plastic strain error < 1e-10: " << (error_ep < 1e-10)
              << ", lateral strain error < 1e-10: " << (error_lateral < 1e-10)
              << std::endl;

      // Release: find the axial stretch with zero axial stress.
      const double       ep_loaded = state.equivalent_plastic_strain;
      double             released  = lambda;
      MaterialPointState unloaded;
      for (unsigned int it = 0; it < 50; ++it)
        {
          lateral = lateral_stretch(law, state, released, lateral);
          law.evaluate(diagonal(released, lateral, lateral),
                       state,
                       StressPart::full,
                       response,
                       &unloaded);
          if (std::abs(response.kirchhoff_stress[0][0]) < 1e-10)
            break;
          // d tau_11 / d lambda along the uniaxial path.
          const double d11 = response.tangent[0][0][0][0];
          const double d1t =
            response.tangent[0][0][1][1] + response.tangent[0][0][2][2];
          const double dt1 = response.tangent[1][1][0][0];
          const double dtt =
            response.tangent[1][1][1][1] + response.tangent[1][1][2][2];
          released -= response.kirchhoff_stress[0][0] / (d11 - d1t * dt1 / dtt);
        }
      deallog << "  released: elastic " << !response.plastic
              << ", plastic strain unchanged "
              << (std::abs(unloaded.equivalent_plastic_strain - ep_loaded) <
                  1e-12)
              << ", stress zero "
              << (std::abs(response.kirchhoff_stress[0][0]) < 1e-8 &&
                  std::abs(response.kirchhoff_stress[1][1]) < 1e-8)
              << ", permanent strain = plastic strain "
              << (std::abs(std::log(released) - ep_loaded) < 1e-8) << std::endl;
    }

  // 3: tangents against central differences.
  {
    Tensor<2, 3> F       = diagonal(1.08, 0.97, 0.99);
    F[0][1]              = 0.12;
    F[1][2]              = -0.05;
    F[2][0]              = 0.03;
    Tensor<2, 3> F_small = diagonal(1.001, 0.9995, 1.0002);
    F_small[0][1]        = 0.0004;

    const J2Plasticity j2(E, nu, hardening(HardeningType::swift));
    MaterialPointState plastic_state;
    {
      FiniteStrainResponse r;
      j2.evaluate(diagonal(1.05, 0.98, 0.98),
                  MaterialPointState(),
                  StressPart::full,
                  r,
                  &plastic_state);
    }
    FiniteStrainResponse r;
    j2.evaluate(F, plastic_state, StressPart::full, r);
    deallog << "J2 at F: plastic " << r.plastic << std::endl;
    j2.evaluate(F_small, MaterialPointState(), StressPart::full, r);
    deallog << "J2 at F_small: plastic " << r.plastic << std::endl;

    const NeoHookean           nh(10., 0.45);
    const NeoHookeanSplit      split(10., 0.49);
    const NeoHookeanSplit      incompressible(10., 0.5);
    const SaintVenantKirchhoff svk(210000., 0.3);
    const std::vector<std::tuple<std::string,
                                 const FiniteStrainMaterial *,
                                 Tensor<2, 3>,
                                 MaterialPointState,
                                 StressPart>>
      cases = {
        {"neo-Hookean", &nh, F, MaterialPointState(), StressPart::full},
        {"neo-Hookean split",
         &split,
         F,
         MaterialPointState(),
         StressPart::full},
        {"neo-Hookean split, isochoric",
         &split,
         F,
         MaterialPointState(),
         StressPart::isochoric},
        {"incompressible, isochoric",
         &incompressible,
         F,
         MaterialPointState(),
         StressPart::isochoric},
        {"Saint Venant-Kirchhoff",
         &svk,
         F,
         MaterialPointState(),
         StressPart::full},
        {"J2, plastic", &j2, F, plastic_state, StressPart::full},
        {"J2, plastic, isochoric",
         &j2,
         F,
         plastic_state,
         StressPart::isochoric},
        {"J2, elastic", &j2, F_small, MaterialPointState(), StressPart::full},
        {"J2, virgin, identity",
         &j2,
         diagonal(1., 1., 1.),
         MaterialPointState(),
         StressPart::full}};
    for (const auto &[name, law, F_case, state, part] : cases)
      deallog << "tangent of " << name
              << " against central differences < 1e-6: "
              << (tangent_error(*law, F_case, state, part) < 1e-6) << std::endl;

    // The stress alone (no derivatives) is the stress of evaluate(), and
    // so are the plastic flag and the updated state.
    for (const auto &[name, law, F_case, state, part] : cases)
      {
        FiniteStrainResponse with_tangent, alone;
        MaterialPointState   state_with_tangent, state_alone;
        law->evaluate(F_case, state, part, with_tangent, &state_with_tangent);
        law->evaluate_stress(F_case, state, part, alone, &state_alone);
        const double scale = std::max(with_tangent.kirchhoff_stress.norm(), 1.);
        deallog
          << "stress alone of " << name << " = stress of evaluate() "
          << "to 1e-13: "
          << ((alone.kirchhoff_stress - with_tangent.kirchhoff_stress).norm() <=
                1e-13 * scale &&
              alone.plastic == with_tangent.plastic &&
              std::abs(state_alone.equivalent_plastic_strain -
                       state_with_tangent.equivalent_plastic_strain) <= 1e-15 &&
              (state_alone.plastic_metric_inverse -
               state_with_tangent.plastic_metric_inverse)
                  .norm() <= 1e-13)
          << std::endl;
      }
  }

  // 4: objectivity under a superposed rigid rotation, step by step.
  {
    const J2Plasticity law(E, nu, hardening(HardeningType::linear));
    Tensor<2, 3>       F = diagonal(1.06, 0.975, 0.98);
    F[0][1]              = 0.04;
    MaterialPointState   state;
    FiniteStrainResponse response;
    law.evaluate(F, state, StressPart::full, response, &state);
    const SymmetricTensor<2, 3> tau0 = response.kirchhoff_stress;
    const double                ep0  = state.equivalent_plastic_strain;
    const Tensor<1, 3>          axis({0.3, -0.5, 0.8});
    double stress_error = 0., invariant_error = 0., ep_error = 0.;
    for (unsigned int step = 1; step <= 36; ++step)
      {
        const Tensor<2, 3> Q = rotation(step * numbers::PI / 18., axis);
        MaterialPointState updated;
        law.evaluate(Q * F, state, StressPart::full, response, &updated);
        state                       = updated;
        const Tensor<2, 3> expected = Q * Tensor<2, 3>(tau0) * transpose(Q);
        stress_error =
          std::max(stress_error,
                   (Tensor<2, 3>(response.kirchhoff_stress) - expected).norm() /
                     tau0.norm());
        invariant_error = std::max(
          {invariant_error,
           std::abs(first_invariant(response.kirchhoff_stress) -
                    first_invariant(tau0)) /
             tau0.norm(),
           std::abs(
             std::sqrt(second_invariant(deviator(response.kirchhoff_stress))) -
             std::sqrt(second_invariant(deviator(tau0)))) /
             tau0.norm(),
           std::abs(std::cbrt(third_invariant(response.kirchhoff_stress)) -
                    std::cbrt(third_invariant(tau0))) /
             tau0.norm()});
        ep_error =
          std::max(ep_error, std::abs(state.equivalent_plastic_strain - ep0));
      }
    deallog << "rotation to 360 deg: plastic before " << (ep0 > 1e-3)
            << ", stress rotates < 1e-10: " << (stress_error < 1e-10)
            << ", invariants < 1e-10: " << (invariant_error < 1e-10)
            << ", no plastic strain < 1e-12: " << (ep_error < 1e-12)
            << std::endl;
  }

  // 5: simple shear of the neo-Hookean laws.
  {
    const double gamma = 0.7;
    Tensor<2, 3> F     = diagonal(1., 1., 1.);
    F[0][1]            = gamma;
    const NeoHookean      nh(10., 0.3);
    const NeoHookeanSplit split(10., 0.5);
    const double          mu = 10. / 2.6;
    FiniteStrainResponse  a, b;
    nh.evaluate(F, MaterialPointState(), StressPart::full, a);
    split.evaluate(F, MaterialPointState(), StressPart::isochoric, b);
    deallog << "simple shear: neo-Hookean "
            << (std::abs(a.kirchhoff_stress[0][1] - mu * gamma) < 1e-12 * mu &&
                std::abs(a.kirchhoff_stress[0][0] - mu * gamma * gamma) <
                  1e-12 * mu)
            << ", split "
            << (std::abs(b.kirchhoff_stress[0][1] - 10. / 3. * gamma) <
                  1e-12 * mu &&
                std::abs(b.kirchhoff_stress[0][0] -
                         2. / 3. * 10. / 3. * gamma * gamma) < 1e-12 * mu)
            << std::endl;
  }

  // 6: bad hardening parameters.
  {
    const auto message = [](const HardeningParameters &p) {
      try
        {
          HardeningLaw law(p);
          return std::string("accepted");
        }
      catch (const ExceptionBase &)
        {
          return std::string("rejected");
        }
    };
    HardeningParameters p = hardening(HardeningType::swift);
    p.exponent            = -0.2;
    deallog << "Swift, negative exponent: " << message(p) << std::endl;
    p              = hardening(HardeningType::power_law_with_yield);
    p.yield_stress = 120.;
    deallog << "power law, yield stress below the curve's start: " << message(p)
            << std::endl;
    p       = hardening(HardeningType::tabulated);
    p.table = {{0., 200.}, {0.1, 150.}};
    deallog << "table, softening: " << message(p) << std::endl;
    p              = hardening(HardeningType::linear);
    p.yield_stress = -5.;
    deallog << "linear, negative yield stress: " << message(p) << std::endl;
  }
}
