#include <common/io/parameter_values.h>

#include <cmath>
#include <sstream>

namespace Common
{
  namespace IO
  {
    double
    get_positive(dealii::ParameterHandler &prm,
                 const std::string        &subsection,
                 const std::string        &entry,
                 const double              max_value,
                 const std::string        &unit)
    {
      const double value = prm.get_double(entry);
      if (!(value > 0. && value <= max_value))
        {
          std::ostringstream text;
          text << subsection << ": '" << entry
               << "' must be positive and at most " << max_value << " " << unit
               << ", got " << value << ".";
          AssertThrow(false, dealii::ExcMessage(text.str()));
        }
      return value;
    }



    double
    get_positive_length(dealii::ParameterHandler &prm,
                        const std::string        &subsection,
                        const std::string        &entry)
    {
      return get_positive(prm, subsection, entry, max_length, "mm");
    }
  } // namespace IO
} // namespace Common
