#include <common/io/json_writer.h>

#include <deal.II/base/exceptions.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace Common
{
  namespace IO
  {
    namespace
    {
      std::string
      number(const double value, const std::string &key)
      {
        AssertThrow(std::isfinite(value),
                    dealii::ExcMessage("Result '" + key +
                                       "' is not a finite number."));
        char buffer[64];
        std::snprintf(buffer, sizeof(buffer), "%.10g", value);
        return buffer;
      }

      std::string
      quoted(const std::string &text)
      {
        std::string out = "\"";
        for (const char c : text)
          {
            if (c == '"' || c == '\\')
              out += '\\';
            if (c == '\n')
              {
                out += "\\n";
                continue;
              }
            out += c;
          }
        return out + "\"";
      }
    } // namespace



    JsonObject &
    JsonObject::set_raw(const std::string &key, const std::string &json_text)
    {
      for (auto &entry : entries)
        if (entry.first == key)
          {
            entry.second = json_text;
            return *this;
          }
      entries.emplace_back(key, json_text);
      return *this;
    }



    JsonObject &
    JsonObject::set(const std::string &key, const double value)
    {
      return set_raw(key, number(value, key));
    }



    JsonObject &
    JsonObject::set(const std::string &key, const unsigned long value)
    {
      return set_raw(key, std::to_string(value));
    }



    JsonObject &
    JsonObject::set(const std::string &key, const unsigned int value)
    {
      return set_raw(key, std::to_string(value));
    }



    JsonObject &
    JsonObject::set(const std::string &key, const int value)
    {
      return set_raw(key, std::to_string(value));
    }



    JsonObject &
    JsonObject::set(const std::string &key, const std::string &value)
    {
      return set_raw(key, quoted(value));
    }



    JsonObject &
    JsonObject::set(const std::string &key, const char *value)
    {
      return set_raw(key, quoted(value));
    }



    JsonObject &
    JsonObject::set(const std::string &key, const bool value)
    {
      return set_raw(key, value ? "true" : "false");
    }



    JsonObject &
    JsonObject::set(const std::string &key, const std::vector<double> &values)
    {
      std::string text = "[";
      for (unsigned int i = 0; i < values.size(); ++i)
        text += (i > 0 ? ", " : "") + number(values[i], key);
      return set_raw(key, text + "]");
    }



    JsonObject &
    JsonObject::set(const std::string               &key,
                    const std::vector<unsigned int> &values)
    {
      std::string text = "[";
      for (unsigned int i = 0; i < values.size(); ++i)
        text += (i > 0 ? ", " : "") + std::to_string(values[i]);
      return set_raw(key, text + "]");
    }



    JsonObject &
    JsonObject::set(const std::string &key, const JsonObject &value)
    {
      // Nested objects are stored unindented and re-indented on output.
      return set_raw(key,
                     "\x01" + std::to_string(entries.size()) + "\x01" +
                       value.to_string(0));
    }



    std::string
    JsonObject::to_string(const unsigned int indent) const
    {
      const std::string  pad(indent + 2, ' ');
      std::ostringstream out;
      out << "{\n";
      for (unsigned int i = 0; i < entries.size(); ++i)
        {
          std::string value = entries[i].second;
          if (!value.empty() && value[0] == '\x01')
            {
              // A nested object: re-indent every line by our depth.
              value            = value.substr(value.find('\x01', 1) + 1);
              std::string body = "";
              for (const char c : value)
                {
                  body += c;
                  if (c == '\n')
                    body += pad;
                }
              value = body;
            }
          out << pad << quoted(entries[i].first) << ": " << value
              << (i + 1 < entries.size() ? "," : "") << "\n";
        }
      out << std::string(indent, ' ') << "}";
      return out.str();
    }



    void
    JsonObject::write(const std::string &filename) const
    {
      const std::string temporary = filename + ".tmp";
      {
        std::ofstream file(temporary);
        AssertThrow(file, dealii::ExcMessage("Cannot write " + filename));
        file << to_string() << "\n";
      }
      AssertThrow(std::rename(temporary.c_str(), filename.c_str()) == 0,
                  dealii::ExcMessage("Cannot write " + filename));
    }
  } // namespace IO
} // namespace Common
