#include <common/io/parameter_values.h>
#include <common/materials/finite_strain_material.h>
#include <common/materials/linear_elastic.h>

#include <deal.II/base/exceptions.h>

#include <Sacado.hpp>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

namespace Common
{
  namespace Materials
  {
    using namespace dealii;

    namespace
    {
      /** Forward-mode number with the nine derivatives by F_kl. */
      using ADNumber = Sacado::Fad::SFad<double, 9>;

      double
      value(const double x)
      {
        return x;
      }

      double
      value(const ADNumber &x)
      {
        return x.val();
      }

      /** A 3x3 matrix of any number type, row by row. */
      template <typename Number>
      using Matrix = std::array<Number, 9>;

      template <typename Number>
      Matrix<Number>
      identity(const double scale = 1.)
      {
        Matrix<Number> m;
        m.fill(Number(0.));
        m[0] = m[4] = m[8] = Number(scale);
        return m;
      }

      template <typename Number>
      Matrix<Number>
      product(const Matrix<Number> &a, const Matrix<Number> &b)
      {
        Matrix<Number> c;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            c[3 * i + j] = a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] +
                           a[3 * i + 2] * b[6 + j];
        return c;
      }

      template <typename Number>
      Matrix<Number>
      transpose(const Matrix<Number> &a)
      {
        Matrix<Number> t;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            t[3 * i + j] = a[3 * j + i];
        return t;
      }

      template <typename Number>
      Number
      trace(const Matrix<Number> &a)
      {
        return a[0] + a[4] + a[8];
      }

      template <typename Number>
      Number
      determinant(const Matrix<Number> &a)
      {
        return a[0] * (a[4] * a[8] - a[5] * a[7]) -
               a[1] * (a[3] * a[8] - a[5] * a[6]) +
               a[2] * (a[3] * a[7] - a[4] * a[6]);
      }

      template <typename Number>
      Matrix<Number>
      inverse(const Matrix<Number> &a)
      {
        const Number   d = determinant(a);
        Matrix<Number> r;
        r[0] = (a[4] * a[8] - a[5] * a[7]) / d;
        r[1] = (a[2] * a[7] - a[1] * a[8]) / d;
        r[2] = (a[1] * a[5] - a[2] * a[4]) / d;
        r[3] = (a[5] * a[6] - a[3] * a[8]) / d;
        r[4] = (a[0] * a[8] - a[2] * a[6]) / d;
        r[5] = (a[2] * a[3] - a[0] * a[5]) / d;
        r[6] = (a[3] * a[7] - a[4] * a[6]) / d;
        r[7] = (a[1] * a[6] - a[0] * a[7]) / d;
        r[8] = (a[0] * a[4] - a[1] * a[3]) / d;
        return r;
      }

      template <typename Number, typename Scalar>
      Matrix<Number>
      scaled(const Matrix<Number> &a, const Scalar &s)
      {
        Matrix<Number> r;
        for (unsigned int i = 0; i < 9; ++i)
          r[i] = a[i] * s;
        return r;
      }

      template <typename Number>
      Matrix<Number>
      sum(const Matrix<Number> &a, const Matrix<Number> &b)
      {
        Matrix<Number> r;
        for (unsigned int i = 0; i < 9; ++i)
          r[i] = a[i] + b[i];
        return r;
      }

      template <typename Number>
      Matrix<Number>
      deviator(const Matrix<Number> &a)
      {
        Matrix<Number> r     = a;
        const Number   third = trace(a) / 3.;
        r[0] -= third;
        r[4] -= third;
        r[8] -= third;
        return r;
      }

      template <typename Number>
      Number
      contract(const Matrix<Number> &a, const Matrix<Number> &b)
      {
        Number s = a[0] * b[0];
        for (unsigned int i = 1; i < 9; ++i)
          s += a[i] * b[i];
        return s;
      }

      /** (a + a^T)/2: removes the round-off asymmetry of products of
       * commuting symmetric matrices. */
      template <typename Number>
      Matrix<Number>
      symmetric_part(const Matrix<Number> &a)
      {
        return scaled(sum(a, transpose(a)), 0.5);
      }

      template <typename Number>
      Matrix<Number>
      from(const SymmetricTensor<2, 3> &t)
      {
        Matrix<Number> m;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            m[3 * i + j] = Number(t[i][j]);
        return m;
      }

      /**
       * Logarithm of a symmetric positive definite matrix b:
       * \f$\ln b = 2\sum_{k\ odd} Z^k/k\f$ with
       * \f$Z = (b - I)(b + I)^{-1}\f$, whose eigenvalues lie in (-1, 1) for
       * any such b. Only products and one inverse: exact derivatives for
       * automatic differentiation, also at repeated eigenvalues.
       */
      template <typename Number>
      Matrix<Number>
      log_spd(const Matrix<Number> &b)
      {
        const Matrix<Number> Z =
          symmetric_part(product(sum(b, identity<Number>(-1.)),
                                 inverse(sum(b, identity<Number>(1.)))));
        const Matrix<Number> Z2     = product(Z, Z);
        Matrix<Number>       term   = Z;
        Matrix<Number>       series = Z;
        for (unsigned int k = 3; k < 20001; k += 2)
          {
            term           = product(term, Z2);
            series         = sum(series, scaled(term, 1. / k));
            double largest = 0.;
            for (const auto &t : term)
              largest = std::max(largest, std::abs(value(t)));
            if (largest < 1e-20)
              break;
          }
        return scaled(symmetric_part(series), 2.);
      }

      /** Exponential of a symmetric matrix (values only), by its
       * eigenvalues. */
      SymmetricTensor<2, 3>
      exponential(const SymmetricTensor<2, 3> &a)
      {
        const auto            eigen = eigenvectors(a);
        SymmetricTensor<2, 3> result;
        for (const auto &[lambda, n] : eigen)
          result += std::exp(lambda) * symmetrize(outer_product(n, n));
        return result;
      }

      SymmetricTensor<2, 3>
      symmetric_value(const Matrix<double> &m)
      {
        SymmetricTensor<2, 3> t;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = i; j < 3; ++j)
            t[i][j] = 0.5 * (m[3 * i + j] + m[3 * j + i]);
        return t;
      }

      /**
       * Evaluate stress(F_ad, tau_ad) of a law with F seeded as the nine
       * independent variables and store tau and d tau/d F.
       */
      template <typename StressFunction>
      void
      differentiate(const Tensor<2, 3>   &F,
                    const StressFunction &stress,
                    FiniteStrainResponse &response)
      {
        Matrix<ADNumber> F_ad;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            F_ad[3 * i + j] = ADNumber(9, 3 * i + j, F[i][j]);
        Matrix<ADNumber> tau;
        stress(F_ad.data(), tau.data());
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            {
              const ADNumber &t = tau[3 * i + j];
              if (j >= i)
                response.kirchhoff_stress[i][j] =
                  0.5 * (t.val() + tau[3 * j + i].val());
              for (unsigned int k = 0; k < 3; ++k)
                for (unsigned int l = 0; l < 3; ++l)
                  response.tangent[i][j][k][l] = t.dx(3 * k + l);
            }
      }

      /** Evaluate stress(F, tau) of a law in plain numbers and store
       * tau. */
      template <typename StressFunction>
      void
      stress_value(const Tensor<2, 3>   &F,
                   const StressFunction &stress,
                   FiniteStrainResponse &response)
      {
        Matrix<double> F_m;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            F_m[3 * i + j] = F[i][j];
        Matrix<double> tau;
        stress(F_m.data(), tau.data());
        response.kirchhoff_stress = symmetric_value(tau);
      }

      std::string
      number(const double x)
      {
        std::ostringstream s;
        s << x;
        return s.str();
      }
    } // namespace



    bool
    FiniteStrainMaterial::is_incompressible() const
    {
      return false;
    }



    std::pair<double, double>
    FiniteStrainMaterial::volumetric_response(const double) const
    {
      AssertThrow(false,
                  ExcMessage("This material law has no volumetric energy."));
      return {0., 0.};
    }



    bool
    FiniteStrainMaterial::has_history() const
    {
      return false;
    }



    void
    FiniteStrainMaterial::evaluate_stress(
      const Tensor<2, 3>       &F,
      const MaterialPointState &state,
      const StressPart          part,
      FiniteStrainResponse     &response,
      MaterialPointState       *updated_state) const
    {
      evaluate(F, state, part, response, updated_state);
    }



    template <class Law>
    void
    HyperelasticMaterial<Law>::evaluate_stress(
      const Tensor<2, 3>       &F,
      const MaterialPointState &state,
      const StressPart          part,
      FiniteStrainResponse     &response,
      MaterialPointState       *updated_state) const
    {
      stress_value(
        F,
        [&](const double *F_m, double *tau) {
          static_cast<const Law &>(*this).stress(F_m, part, tau);
        },
        response);
      response.plastic = false;
      if (updated_state != nullptr)
        *updated_state = state;
    }



    template <class Law>
    void
    HyperelasticMaterial<Law>::evaluate(const Tensor<2, 3>       &F,
                                        const MaterialPointState &state,
                                        const StressPart          part,
                                        FiniteStrainResponse     &response,
                                        MaterialPointState *updated_state) const
    {
      differentiate(
        F,
        [&](const ADNumber *F_ad, ADNumber *tau) {
          static_cast<const Law &>(*this).stress(F_ad, part, tau);
        },
        response);
      response.plastic = false;
      if (updated_state != nullptr)
        *updated_state = state;
    }



    // ------------------------------------------------------------------
    // Parameters

    void
    FiniteStrainMaterialParameters::declare_parameters(
      ParameterHandler  &prm,
      const std::string &subsection)
    {
      prm.enter_subsection(subsection);
      {
        prm.declare_entry(
          "Finite strain model",
          "neo-Hookean",
          Patterns::Selection("neo-Hookean|neo-Hookean split|"
                              "Saint Venant-Kirchhoff|J2 plasticity"),
          "Law of the body under finite-strain kinematics (with Young's "
          "modulus and Poisson's ratio): neo-Hookean: tau = mu (b - I) + "
          "lambda ln J I; neo-Hookean split: mu dev(J^(-2/3) b) + "
          "K J (J - 1) I, exactly incompressible at Poisson's ratio 0.5 "
          "(which needs the mixed element); Saint Venant-Kirchhoff: Hooke's "
          "law between the second Piola-Kirchhoff stress and the "
          "Green-Lagrange strain; J2 plasticity: von Mises plasticity with "
          "Hencky elasticity and the hardening entries below. Under "
          "small-strain kinematics every elastic law is Hooke's law with "
          "these constants, and J2 plasticity is refused.");
        HardeningParameters::declare_parameters(prm);
      }
      prm.leave_subsection();
    }



    void
    FiniteStrainMaterialParameters::parse_parameters(
      ParameterHandler  &prm,
      const std::string &subsection)
    {
      prm.enter_subsection(subsection);
      {
        const std::string name = prm.get("Finite strain model");
        model =
          name == "neo-Hookean"       ? FiniteStrainModel::neo_hookean :
          name == "neo-Hookean split" ? FiniteStrainModel::neo_hookean_split :
          name == "J2 plasticity"     ? FiniteStrainModel::j2_plasticity :
                                        FiniteStrainModel::saint_venant_kirchhoff;
        youngs_modulus = IO::get_positive(prm,
                                          subsection,
                                          "Young's modulus",
                                          IO::max_modulus,
                                          "MPa");
        poisson_ratio  = prm.get_double("Poisson's ratio");
        const bool may_be_incompressible =
          model == FiniteStrainModel::neo_hookean_split;
        AssertThrow(poisson_ratio > -1. &&
                      (poisson_ratio < 0.5 ||
                       (may_be_incompressible && poisson_ratio == 0.5)),
                    ExcMessage(subsection +
                               ": Poisson's ratio must lie in (-1, 0.5)" +
                               (may_be_incompressible ?
                                  std::string(" or be 0.5 (incompressible)") :
                                  std::string(" for the ") + name +
                                    " law ('Finite strain model')") +
                               ", got " + number(poisson_ratio) + "."));
        if (model == FiniteStrainModel::j2_plasticity)
          hardening.parse_parameters(prm, youngs_modulus, subsection);
      }
      prm.leave_subsection();
    }



    std::unique_ptr<FiniteStrainMaterial>
    create_finite_strain_material(const FiniteStrainMaterialParameters &p)
    {
      switch (p.model)
        {
          case FiniteStrainModel::neo_hookean:
            return std::make_unique<NeoHookean>(p.youngs_modulus,
                                                p.poisson_ratio);
          case FiniteStrainModel::neo_hookean_split:
            return std::make_unique<NeoHookeanSplit>(p.youngs_modulus,
                                                     p.poisson_ratio);
          case FiniteStrainModel::saint_venant_kirchhoff:
            return std::make_unique<SaintVenantKirchhoff>(p.youngs_modulus,
                                                          p.poisson_ratio);
          case FiniteStrainModel::j2_plasticity:
            return std::make_unique<J2Plasticity>(p.youngs_modulus,
                                                  p.poisson_ratio,
                                                  p.hardening);
        }
      return nullptr;
    }



    // ------------------------------------------------------------------
    // Compressible neo-Hookean

    template <class Law>
    CompressibleHyperelasticMaterial<Law>::CompressibleHyperelasticMaterial(
      const double       E,
      const double       nu,
      const std::string &name)
    {
      AssertThrow(E > 0. && nu > -1. && nu < 0.5,
                  ExcMessage(name + ": needs E > 0 and -1 < nu < 0.5."));
      mu     = E / (2. * (1. + nu));
      lambda = E * nu / ((1. + nu) * (1. - 2. * nu));
    }



    template <class Law>
    bool
    CompressibleHyperelasticMaterial<Law>::has_volumetric_split() const
    {
      return false;
    }



    template <class Law>
    double
    CompressibleHyperelasticMaterial<Law>::shear_modulus() const
    {
      return mu;
    }



    template <class Law>
    double
    CompressibleHyperelasticMaterial<Law>::bulk_modulus() const
    {
      return lambda + 2. * mu / 3.;
    }



    NeoHookean::NeoHookean(const double E, const double nu)
      : CompressibleHyperelasticMaterial<NeoHookean>(E, nu, "neo-Hookean")
    {}



    template <typename Number>
    void
    NeoHookean::stress(const Number    *F_in,
                       const StressPart part,
                       Number          *tau) const
    {
      AssertThrow(part == StressPart::full,
                  ExcMessage("The compressible neo-Hookean law has no "
                             "volumetric-isochoric split; use the split "
                             "law with the mixed element."));
      using std::log;
      Matrix<Number> F;
      std::copy(F_in, F_in + 9, F.begin());
      const Matrix<Number> b = product(F, transpose(F));
      const Number         J = determinant(F);
      const Matrix<Number> t = sum(scaled(sum(b, identity<Number>(-1.)), mu),
                                   scaled(identity<Number>(), lambda * log(J)));
      std::copy(t.begin(), t.end(), tau);
    }



    // ------------------------------------------------------------------
    // Neo-Hookean with a volumetric-isochoric split

    NeoHookeanSplit::NeoHookeanSplit(const double E, const double nu)
    {
      AssertThrow(E > 0. && nu > -1. && nu <= 0.5,
                  ExcMessage("neo-Hookean split: needs E > 0 and "
                             "-1 < nu <= 0.5."));
      mu             = E / (2. * (1. + nu));
      incompressible = nu == 0.5;
      kappa = incompressible ? std::numeric_limits<double>::infinity() :
                               E / (3. * (1. - 2. * nu));
    }



    template <typename Number>
    void
    NeoHookeanSplit::stress(const Number    *F_in,
                            const StressPart part,
                            Number          *tau) const
    {
      AssertThrow(part == StressPart::isochoric || !incompressible,
                  ExcMessage("An exactly incompressible law needs an "
                             "element with its own pressure field (the "
                             "mixed element)."));
      using std::pow;
      Matrix<Number> F;
      std::copy(F_in, F_in + 9, F.begin());
      const Matrix<Number> b = product(F, transpose(F));
      const Number         J = determinant(F);
      Matrix<Number>       t = scaled(deviator(b), mu * pow(J, -2. / 3.));
      if (part == StressPart::full)
        t = sum(t, scaled(identity<Number>(), kappa * J * (J - 1.)));
      std::copy(t.begin(), t.end(), tau);
    }



    bool
    NeoHookeanSplit::has_volumetric_split() const
    {
      return true;
    }



    bool
    NeoHookeanSplit::is_incompressible() const
    {
      return incompressible;
    }



    std::pair<double, double>
    NeoHookeanSplit::volumetric_response(const double J) const
    {
      AssertThrow(!incompressible,
                  ExcMessage("An incompressible law has no volumetric "
                             "energy."));
      return {kappa * (J - 1.), kappa};
    }



    double
    NeoHookeanSplit::shear_modulus() const
    {
      return mu;
    }



    double
    NeoHookeanSplit::bulk_modulus() const
    {
      return kappa;
    }



    // ------------------------------------------------------------------
    // Saint Venant-Kirchhoff

    SaintVenantKirchhoff::SaintVenantKirchhoff(const double E, const double nu)
      : CompressibleHyperelasticMaterial<SaintVenantKirchhoff>(
          E,
          nu,
          "Saint Venant-Kirchhoff")
    {}



    template <typename Number>
    void
    SaintVenantKirchhoff::stress(const Number    *F_in,
                                 const StressPart part,
                                 Number          *tau) const
    {
      AssertThrow(part == StressPart::full,
                  ExcMessage("The Saint Venant-Kirchhoff law has no "
                             "volumetric-isochoric split."));
      Matrix<Number> F;
      std::copy(F_in, F_in + 9, F.begin());
      const Matrix<Number> E =
        scaled(sum(product(transpose(F), F), identity<Number>(-1.)), 0.5);
      const Matrix<Number> S =
        sum(scaled(identity<Number>(), lambda * trace(E)), scaled(E, 2. * mu));
      const Matrix<Number> t = product(product(F, S), transpose(F));
      std::copy(t.begin(), t.end(), tau);
    }



    // ------------------------------------------------------------------
    // J2 plasticity

    J2Plasticity::J2Plasticity(const double               E,
                               const double               nu,
                               const HardeningParameters &hardening)
      : hardening_law(hardening)
    {
      AssertThrow(E > 0. && nu > -1. && nu < 0.5,
                  ExcMessage("J2 plasticity: needs E > 0 and -1 < nu < 0.5."));
      G = E / (2. * (1. + nu));
      K = E / (3. * (1. - 2. * nu));
    }



    template <typename Number>
    void
    J2Plasticity::stress(const Number             *F_in,
                         const MaterialPointState &state,
                         const StressPart          part,
                         Number                   *tau,
                         MaterialPointState       *updated_state,
                         bool                     &plastic) const
    {
      using std::sqrt;
      Matrix<Number> F;
      std::copy(F_in, F_in + 9, F.begin());
      // Elastic predictor: b_e = F C_p^{-1} F^T, eps_e = ln(b_e)/2.
      const Matrix<Number> be_trial = symmetric_part(
        product(product(F, from<Number>(state.plastic_metric_inverse)),
                transpose(F)));
      const Matrix<Number> eps_trial         = scaled(log_spd(be_trial), 0.5);
      const Number         volumetric_strain = trace(eps_trial);
      Matrix<Number>       s = scaled(deviator(eps_trial), 2. * G);

      Matrix<double> s_value;
      for (unsigned int i = 0; i < 9; ++i)
        s_value[i] = value(s[i]);
      const double q_trial   = std::sqrt(1.5 * contract(s_value, s_value));
      const double ep        = state.equivalent_plastic_strain;
      const double f_trial   = q_trial - hardening_law.flow_stress(ep);
      double       increment = 0.;
      plastic = f_trial > 1e-12 * hardening_law.initial_yield_stress();
      if (plastic)
        {
          // Radial return: q_trial - 3 G dg = sigma_f(ep + dg), solved in
          // double precision; one Newton step in the number type then
          // carries the exact derivative of dg (implicit function theorem).
          for (unsigned int it = 0; it < 100; ++it)
            {
              const auto [flow, slope] = hardening_law.evaluate(ep + increment);
              const double r           = q_trial - 3. * G * increment - flow;
              increment += r / (3. * G + slope);
              if (std::abs(r) <= 1e-14 * flow)
                break;
            }
          const auto [flow, slope] = hardening_law.evaluate(ep + increment);
          const Number q           = sqrt(1.5 * contract(s, s));
          const Number dg =
            increment + (q - 3. * G * increment - flow) / (3. * G + slope);
          s = scaled(s, 1. - 3. * G * dg / q);
        }
      Matrix<Number> t = s;
      if (part == StressPart::full)
        t = sum(t, scaled(identity<Number>(), K * volumetric_strain));
      std::copy(t.begin(), t.end(), tau);

      if (updated_state != nullptr)
        {
          // eps_e = s/(2G) + tr(eps)/3 I; b_e = exp(2 eps_e);
          // C_p^{-1} = F^{-1} b_e F^{-T}.
          Matrix<double> eps_e, F_value;
          for (unsigned int i = 0; i < 9; ++i)
            {
              eps_e[i]   = value(s[i]) / (2. * G);
              F_value[i] = value(F[i]);
            }
          const double third = value(volumetric_strain) / 3.;
          eps_e[0] += third;
          eps_e[4] += third;
          eps_e[8] += third;
          const SymmetricTensor<2, 3> be =
            exponential(symmetric_value(scaled(eps_e, 2.)));
          const Matrix<double> F_inverse = inverse(F_value);
          updated_state->plastic_metric_inverse =
            symmetric_value(product(product(F_inverse, from<double>(be)),
                                    transpose(F_inverse)));
          updated_state->equivalent_plastic_strain = ep + increment;
        }
    }



    void
    J2Plasticity::evaluate_stress(const Tensor<2, 3>       &F,
                                  const MaterialPointState &state,
                                  const StressPart          part,
                                  FiniteStrainResponse     &response,
                                  MaterialPointState       *updated_state) const
    {
      bool plastic = false;
      stress_value(
        F,
        [&](const double *F_m, double *tau) {
          stress(F_m, state, part, tau, updated_state, plastic);
        },
        response);
      response.plastic = plastic;
    }



    void
    J2Plasticity::evaluate(const Tensor<2, 3>       &F,
                           const MaterialPointState &state,
                           const StressPart          part,
                           FiniteStrainResponse     &response,
                           MaterialPointState       *updated_state) const
    {
      bool plastic = false;
      differentiate(
        F,
        [&](const ADNumber *F_ad, ADNumber *tau) {
          stress(F_ad, state, part, tau, updated_state, plastic);
        },
        response);
      response.plastic = plastic;
    }



    bool
    J2Plasticity::has_volumetric_split() const
    {
      return true;
    }



    std::pair<double, double>
    J2Plasticity::volumetric_response(const double J) const
    {
      // U = K/2 (ln J)^2.
      return {K * std::log(J) / J, K * (1. - std::log(J)) / (J * J)};
    }



    bool
    J2Plasticity::has_history() const
    {
      return true;
    }



    double
    J2Plasticity::shear_modulus() const
    {
      return G;
    }



    double
    J2Plasticity::bulk_modulus() const
    {
      return K;
    }



    template class HyperelasticMaterial<NeoHookean>;
    template class HyperelasticMaterial<NeoHookeanSplit>;
    template class HyperelasticMaterial<SaintVenantKirchhoff>;
    template class CompressibleHyperelasticMaterial<NeoHookean>;
    template class CompressibleHyperelasticMaterial<SaintVenantKirchhoff>;



    const HardeningLaw &
    J2Plasticity::hardening() const
    {
      return hardening_law;
    }



    double
    von_mises(const SymmetricTensor<2, 3> &stress)
    {
      const SymmetricTensor<2, 3> s = deviator(stress);
      return std::sqrt(1.5 * scalar_product(s, s));
    }



    SymmetricTensor<2, 3>
    logarithm(const SymmetricTensor<2, 3> &b)
    {
      return symmetric_value(log_spd(from<double>(b)));
    }
  } // namespace Materials
} // namespace Common
