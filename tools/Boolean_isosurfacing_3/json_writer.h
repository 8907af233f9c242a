// A minimal JSON writer for the tools' --json summaries (Debian's Boost has
// no Boost.JSON header): objects keep their keys in insertion order, strings
// are escaped (and made valid UTF-8 first), and a number that is not finite
// is written as null, so the output always parses.

#ifndef BISO_TOOLS_JSON_WRITER_H
#define BISO_TOOLS_JSON_WRITER_H

#include "tool_support.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace biso_tools {

inline std::string json_string(const std::string& s)
{
  // printable() escapes control bytes and invalid UTF-8 as the text "\xNN";
  // its backslashes are escaped below like any other.
  const std::string text = printable(s);
  std::string out = "\"";
  for(char c : text)
  {
    if(c == '"' || c == '\\')
      out += '\\';
    out += c;
  }
  return out + "\"";
}

inline std::string json_number(double v)
{
  if(!std::isfinite(v))
    return "null";
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

inline std::string json_string_array(const std::vector<std::string>& items)
{
  std::string out = "[";
  for(std::size_t i = 0; i < items.size(); ++i)
    out += (i ? ", " : "") + json_string(items[i]);
  return out + "]";
}

inline std::string json_number_array(const std::vector<double>& items)
{
  std::string out = "[";
  for(std::size_t i = 0; i < items.size(); ++i)
    out += (i ? ", " : "") + json_number(items[i]);
  return out + "]";
}

/// A JSON object; setting a key again replaces its value.
class Json_object
{
public:
  void set_raw(const std::string& key, std::string json)
  {
    for(auto& member : m_members)
      if(member.first == key)
      {
        member.second = std::move(json);
        return;
      }
    m_members.emplace_back(key, std::move(json));
  }
  void set(const std::string& key, double v) { set_raw(key, json_number(v)); }
  void set(const std::string& key, std::size_t v) { set_raw(key, std::to_string(v)); }
  void set(const std::string& key, int v) { set_raw(key, std::to_string(v)); }
  void set(const std::string& key, bool v) { set_raw(key, v ? "true" : "false"); }
  void set(const std::string& key, const std::string& v) { set_raw(key, json_string(v)); }
  void set(const std::string& key, const char* v) { set_raw(key, json_string(v)); }
  void set_null(const std::string& key) { set_raw(key, "null"); }
  void set(const std::string& key, const Json_object& v) { set_raw(key, v.str()); }
  /// The members of `other`, after these.
  void append(const Json_object& other)
  {
    for(const auto& member : other.m_members)
      set_raw(member.first, member.second);
  }
  bool empty() const { return m_members.empty(); }

  std::string str() const
  {
    std::string out = "{";
    for(std::size_t i = 0; i < m_members.size(); ++i)
      out += (i ? ", " : "") + json_string(m_members[i].first) + ": " + m_members[i].second;
    return out + "}";
  }

private:
  std::vector<std::pair<std::string, std::string>> m_members;
};

} // namespace biso_tools

#endif // BISO_TOOLS_JSON_WRITER_H
