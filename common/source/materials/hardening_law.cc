#include <common/materials/hardening_law.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace Common
{
  namespace Materials
  {
    using namespace dealii;

    namespace
    {
      std::string
      number(const double value)
      {
        std::ostringstream stream;
        stream << value;
        return stream.str();
      }



      /** Parse "e1:s1, e2:s2, ..." into pairs; throws naming the entry. */
      std::vector<std::pair<double, double>>
      parse_table(const std::string &text, const std::string &subsection)
      {
        std::vector<std::pair<double, double>> table;
        for (const auto &item : Utilities::split_string_list(text, ','))
          {
            const auto pair = Utilities::split_string_list(item, ':');
            AssertThrow(pair.size() == 2,
                        ExcMessage(subsection +
                                   ": Hardening table: expected "
                                   "'plastic strain:stress' pairs, got '" +
                                   item + "'."));
            try
              {
                table.emplace_back(Utilities::string_to_double(pair[0]),
                                   Utilities::string_to_double(pair[1]));
              }
            catch (...)
              {
                AssertThrow(false,
                            ExcMessage(subsection + ": Hardening table: '" +
                                       item + "' is not a pair of numbers."));
              }
          }
        return table;
      }

      /** What makes the parameters inconsistent, or empty. */
      std::string
      inconsistency(const HardeningParameters &data)
      {
        if (data.type != HardeningType::tabulated && !(data.yield_stress > 0.))
          return "Yield stress must be positive, got " +
                 number(data.yield_stress) + " MPa.";
        switch (data.type)
          {
            case HardeningType::linear:
              if (!(data.hardening_modulus >= 0.))
                return "Hardening modulus must not be negative, got " +
                       number(data.hardening_modulus) + " MPa.";
              break;
            case HardeningType::swift:
              if (!(data.strength_coefficient > 0.))
                return "Strength coefficient must be positive, got " +
                       number(data.strength_coefficient) + " MPa.";
              if (!(data.exponent > 0.))
                return "Hardening exponent of the Swift law must be "
                       "positive, got " +
                       number(data.exponent) + ".";
              break;
            case HardeningType::power_law_with_yield:
              {
                if (!(data.strength_coefficient > 0.))
                  return "Strength coefficient must be positive, got " +
                         number(data.strength_coefficient) + " MPa.";
                if (!(data.exponent >= 0. && data.exponent < 1.))
                  return "Hardening exponent of the power law with yield "
                         "must lie in [0, 1), got " +
                         number(data.exponent) + ".";
                if (!(data.youngs_modulus > 0.))
                  return "the power law with yield needs a positive "
                         "Young's modulus.";
                // Where K eps^n meets the elastic line sigma = E eps: the
                // stress at which the power curve starts.
                const double start =
                  std::pow(data.strength_coefficient *
                             std::pow(data.youngs_modulus, -data.exponent),
                           1. / (1. - data.exponent));
                if (data.yield_stress < start * (1. - 1e-12))
                  return "Yield stress " + number(data.yield_stress) +
                         " MPa lies below the start of the power curve, " +
                         number(start) +
                         " MPa (where K eps^n meets the elastic line).";
                break;
              }
            case HardeningType::tabulated:
              if (data.table.empty() || data.table.front().first != 0.)
                return "Hardening table must start at plastic strain 0.";
              if (!(data.table.front().second > 0.))
                return "Hardening table must start at a positive stress.";
              for (unsigned int i = 1; i < data.table.size(); ++i)
                {
                  if (!(data.table[i].first > data.table[i - 1].first))
                    return "Hardening table: plastic strains must "
                           "increase.";
                  if (!(data.table[i].second >= data.table[i - 1].second))
                    return "Hardening table: the flow stress must not "
                           "decrease (softening is not supported).";
                }
              break;
          }
        // Metals yield at strains above 1e-4 (annealed aluminium and
        // copper: about 3e-4). A yield strain below 1e-6 is a unit error
        // (a modulus in Pa against stresses in MPa), and its return mapping
        // cannot be solved to the Newton tolerance.
        const double initial_flow_stress =
          data.type == HardeningType::tabulated ? data.table.front().second :
                                                  data.yield_stress;
        if (data.youngs_modulus > 0. &&
            initial_flow_stress < 1e-6 * data.youngs_modulus)
          return "the initial yield strain, Yield stress / Young's modulus "
                 "= " +
                 number(initial_flow_stress / data.youngs_modulus) +
                 ", is below 1e-6: no metal yields at so small a strain "
                 "(both in MPa).";
        return "";
      }
    } // namespace



    void
    HardeningParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Hardening law",
        "linear",
        Patterns::Selection("linear|Swift|power law with yield|tabulated"),
        "Isotropic hardening of the flow stress sigma_f against the "
        "equivalent plastic strain ep: linear: sigma_y + H ep; Swift: "
        "K (e0 + ep)^n with e0 = (sigma_y/K)^(1/n), so that the curve "
        "starts at sigma_y; power law with yield: max(sigma_y, K (ep + "
        "sigma/E)^n), Hollomon in the total uniaxial strain with a plateau "
        "at sigma_y; tabulated: piecewise linear through the Hardening "
        "table, continued with its last slope.");
      prm.declare_entry("Yield stress",
                        "200",
                        Patterns::Double(),
                        "Initial yield stress sigma_y. Units: MPa. "
                        "Positive (not read by the tabulated law).");
      prm.declare_entry("Hardening modulus",
                        "0",
                        Patterns::Double(),
                        "Slope H of the linear law. Units: MPa. >= 0 "
                        "(0: perfectly plastic).");
      prm.declare_entry("Strength coefficient",
                        "500",
                        Patterns::Double(),
                        "Coefficient K of the Swift and power laws. Units: "
                        "MPa. Positive.");
      prm.declare_entry("Hardening exponent",
                        "0.2",
                        Patterns::Double(),
                        "Exponent n of the Swift and power laws. "
                        "Dimensionless; Swift: n > 0; power law with "
                        "yield: 0 <= n < 1.");
      prm.declare_entry("Hardening table",
                        "0:200",
                        Patterns::Anything(),
                        "Tabulated law: comma-separated pairs 'plastic "
                        "strain:flow stress' (dimensionless:MPa), the first "
                        "at plastic strain 0, strains increasing, stresses "
                        "not decreasing.");
    }



    void
    HardeningParameters::parse_parameters(ParameterHandler  &prm,
                                          const double       E,
                                          const std::string &subsection)
    {
      const std::string law = prm.get("Hardening law");
      type                  = law == "linear"    ? HardeningType::linear :
                              law == "Swift"     ? HardeningType::swift :
                              law == "tabulated" ? HardeningType::tabulated :
                                                   HardeningType::power_law_with_yield;
      yield_stress          = prm.get_double("Yield stress");
      hardening_modulus     = prm.get_double("Hardening modulus");
      strength_coefficient  = prm.get_double("Strength coefficient");
      exponent              = prm.get_double("Hardening exponent");
      youngs_modulus        = E;
      if (type == HardeningType::tabulated)
        table = parse_table(prm.get("Hardening table"), subsection);
      const std::string problem = inconsistency(*this);
      AssertThrow(problem.empty(), ExcMessage(subsection + ": " + problem));
    }



    HardeningLaw::HardeningLaw(const HardeningParameters &parameters)
      : data(parameters)
    {
      const std::string problem = inconsistency(data);
      AssertThrow(problem.empty(), ExcMessage(problem));
      if (data.type == HardeningType::swift)
        swift_prestrain =
          std::pow(data.yield_stress / data.strength_coefficient,
                   1. / data.exponent);
      if (data.type == HardeningType::tabulated)
        data.yield_stress = data.table.front().second;
    }



    std::pair<double, double>
    HardeningLaw::evaluate(const double ep_in) const
    {
      const double ep = std::max(ep_in, 0.);
      switch (data.type)
        {
          case HardeningType::linear:
            return {data.yield_stress + data.hardening_modulus * ep,
                    data.hardening_modulus};
          case HardeningType::swift:
            {
              const double K = data.strength_coefficient, n = data.exponent;
              const double base = swift_prestrain + ep;
              return {K * std::pow(base, n), K * n * std::pow(base, n - 1.)};
            }
          case HardeningType::power_law_with_yield:
            {
              const double K = data.strength_coefficient, n = data.exponent,
                           E   = data.youngs_modulus;
              const auto curve = [&](const double s) {
                return K * std::pow(ep + s / E, n);
              };
              if (curve(data.yield_stress) <= data.yield_stress)
                return {data.yield_stress, 0.};
              // s = K (ep + s/E)^n: the root above sigma_y, by Newton's
              // method on the convex function s - K (ep + s/E)^n.
              double s = curve(data.yield_stress);
              for (unsigned int it = 0; it < 100; ++it)
                {
                  const double dh = K * n * std::pow(ep + s / E, n - 1.);
                  const double g  = s - curve(s);
                  const double ds = -g / (1. - dh / E);
                  s += ds;
                  if (std::abs(ds) <= 1e-15 * s)
                    break;
                }
              const double dh = K * n * std::pow(ep + s / E, n - 1.);
              return {s, dh / (1. - dh / E)};
            }
          case HardeningType::tabulated:
            {
              const auto &t = data.table;
              if (t.size() == 1)
                return {t[0].second, 0.};
              unsigned int i = 1;
              while (i + 1 < t.size() && ep > t[i].first)
                ++i;
              const double slope =
                (t[i].second - t[i - 1].second) / (t[i].first - t[i - 1].first);
              return {t[i - 1].second + slope * (ep - t[i - 1].first), slope};
            }
        }
      return {0., 0.};
    }



    double
    HardeningLaw::flow_stress(const double plastic_strain) const
    {
      return evaluate(plastic_strain).first;
    }



    double
    HardeningLaw::slope(const double plastic_strain) const
    {
      return evaluate(plastic_strain).second;
    }



    double
    HardeningLaw::initial_yield_stress() const
    {
      return data.yield_stress;
    }



    const HardeningParameters &
    HardeningLaw::parameters() const
    {
      return data;
    }
  } // namespace Materials
} // namespace Common
