/**
 * @file parameter_values.h
 * Reading entries whose valid range a ParameterHandler pattern cannot
 * state (an open interval, a finite bound), with the one-line message of
 * the suite's input errors naming the entry.
 */
#ifndef common_io_parameter_values_h
#define common_io_parameter_values_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace Common
{
  namespace IO
  {
    /** @brief Largest length the suite's geometries accept (mm): 1 km. */
    constexpr double max_length = 1e6;

    /** @brief Largest elastic modulus the suite's materials accept (MPa):
     * a million times diamond's. A body that stiff is modelled as rigid;
     * values near the largest double overflow the stiffness matrix. */
    constexpr double max_modulus = 1e12;

    /**
     * @brief Read the entry @p entry of the current subsection of @p prm,
     * which must be positive and at most @p max_value (in @p unit).
     * @param[in] subsection The subsection's name, as the message names it.
     * @throws dealii::ExcMessage "<subsection>: '<entry>' must be positive
     * and at most <max_value> <unit>, got <value>." otherwise.
     */
    double
    get_positive(dealii::ParameterHandler &prm,
                 const std::string        &subsection,
                 const std::string        &entry,
                 const double              max_value,
                 const std::string        &unit);

    /**
     * @brief Read the length @p entry of the current subsection of @p prm,
     * which must be positive and at most max_length (mm).
     * @param[in] subsection The subsection's name, as the message names it.
     * @throws dealii::ExcMessage "<subsection>: '<entry>' must be positive
     * and at most 1e6 mm, got <value>." otherwise.
     */
    double
    get_positive_length(dealii::ParameterHandler &prm,
                        const std::string        &subsection,
                        const std::string        &entry);
  } // namespace IO
} // namespace Common

#endif
