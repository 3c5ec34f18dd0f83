#include <common/io/parameter_values.h>

#include <cmath>
#include <sstream>

namespace Common
{
  namespace IO
  {
    double
    get_positive_length(dealii::ParameterHandler &prm,
                        const std::string        &subsection,
                        const std::string        &entry)
    {
      const double value = prm.get_double(entry);
      if (!(value > 0. && value <= max_length))
        {
          std::ostringstream text;
          text << subsection << ": '" << entry
               << "' must be positive and at most " << max_length << " mm, got "
               << value << ".";
          AssertThrow(false, dealii::ExcMessage(text.str()));
        }
      return value;
    }
  } // namespace IO
} // namespace Common
