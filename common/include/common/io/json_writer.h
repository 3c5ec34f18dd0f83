/**
 * @file json_writer.h
 * A minimal ordered JSON object for result files (summary.json). Keys keep
 * their insertion order so that files diff cleanly; non-finite numbers are
 * refused, so no result file can carry NaN.
 */
#ifndef common_io_json_writer_h
#define common_io_json_writer_h

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace Common
{
  namespace IO
  {
    /**
     * @brief JSON object with ordered keys: numbers, strings, booleans,
     * number arrays and nested objects.
     */
    class JsonObject
    {
    public:
      /** @brief Set a number; throws if @p value is not finite. */
      JsonObject &
      set(const std::string &key, const double value);

      /** @brief Set an integer. */
      JsonObject &
      set(const std::string &key, const unsigned long value);

      /** @brief Set an integer. */
      JsonObject &
      set(const std::string &key, const unsigned int value);

      /** @brief Set an integer. */
      JsonObject &
      set(const std::string &key, const int value);

      /** @brief Set a string. */
      JsonObject &
      set(const std::string &key, const std::string &value);

      /** @brief Set a string. */
      JsonObject &
      set(const std::string &key, const char *value);

      /** @brief Set a boolean. */
      JsonObject &
      set(const std::string &key, const bool value);

      /** @brief Set an array of numbers; throws if one is not finite. */
      JsonObject &
      set(const std::string &key, const std::vector<double> &values);

      /** @brief Set an array of integers. */
      JsonObject &
      set(const std::string &key, const std::vector<unsigned int> &values);

      /** @brief Set a nested object. */
      JsonObject &
      set(const std::string &key, const JsonObject &value);

      /** @brief Serialise with two-space indentation. */
      std::string
      to_string(const unsigned int indent = 0) const;

      /**
       * @brief Write to @p filename atomically (through a temporary file and
       * a rename), so that an interrupted run never leaves a partial file.
       */
      void
      write(const std::string &filename) const;

    private:
      std::vector<std::pair<std::string, std::string>> entries;

      JsonObject &
      set_raw(const std::string &key, const std::string &json_text);
    };
  } // namespace IO
} // namespace Common

#endif
