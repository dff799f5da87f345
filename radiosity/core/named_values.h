#pragma once

// An enum's names on the command line and in reports, one table per enum: parsing, printing, the
// help texts and the command line's choice checks all read that table, so a new value is one row.
#include <string>
#include <vector>

#include "radiosity/core/check.h"
#include "radiosity/core/errors.h"

namespace rad {

template <class Enum>
struct NamedValue {
  const char* name;
  Enum value;
};

template <class Enum>
using NameTable = std::vector<NamedValue<Enum>>;

// The names in the table's order.
template <class Enum>
std::vector<std::string> tableNames(const NameTable<Enum>& table) {
  std::vector<std::string> names;
  for (const NamedValue<Enum>& row : table) names.emplace_back(row.name);
  return names;
}

// "a | b | c", for help texts and errors.
template <class Enum>
std::string joinTableNames(const NameTable<Enum>& table, const std::string& separator = " | ") {
  std::string joined;
  for (const NamedValue<Enum>& row : table) joined += (joined.empty() ? "" : separator) + row.name;
  return joined;
}

// The name of a value; a value without a row is a bug (the table is the enum's only list).
template <class Enum>
std::string nameOf(const NameTable<Enum>& table, Enum value) {
  for (const NamedValue<Enum>& row : table)
    if (row.value == value) return row.name;
  RAD_CHECK_MSG(false, "an enum value without a name in its table");
  return "";
}

// The value named `name`; InputError "unknown WHAT 'name' (expected a | b | c)" otherwise.
template <class Enum>
Enum parseName(const NameTable<Enum>& table, const std::string& name, const std::string& what) {
  for (const NamedValue<Enum>& row : table)
    if (name == row.name) return row.value;
  throw InputError("unknown " + what + " '" + name + "' (expected " + joinTableNames(table) + ")");
}

}  // namespace rad
