// Strict checks of the fields of a JSON file that hecal reads back (report_input.h: the result
// files `hecal report` shows, docs/report.md "Bad input"): each check names the file and the
// field's JSON path in its InputError, e.g.
//   result.json: field results[0].X.matrix: expected a 4x4 matrix of numbers (fix: …)
// and nothing is read past the first bad field. Numbers must be finite.
#pragma once

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "hecal/core/error.h"

namespace hecal::report {

// Checks fields below one object; `path` is the JSON path shown in errors ("results[0].X",
// "" at the top level).
class JsonChecker {
 public:
  using json = nlohmann::json;
  // `fix` (what to give instead) ends every error; `source` and `fix` outlive the checker.
  JsonChecker(const std::string& source, const json& value, std::string path, const char* fix)
      : source_(source), value_(value), path_(std::move(path)), fix_(fix) {}

  [[noreturn]] void Fail(const std::string& field, const std::string& expected) const {
    throw InputError(source_, 0, "field " + Join(field) + ": expected " + expected, fix_);
  }

  const json& Get(const std::string& field) const {
    if (!value_.is_object()) Fail("", "an object");
    const auto it = value_.find(field);
    if (it == value_.end())
      throw InputError(source_, 0, "field " + Join(field) + " is missing", fix_);
    return *it;
  }
  bool Has(const std::string& field) const { return value_.contains(field); }

  JsonChecker Object(const std::string& field) const {
    const json& v = Get(field);
    if (!v.is_object()) Fail(field, "an object");
    return {source_, v, Join(field), fix_};
  }
  void String(const std::string& field) const {
    if (!Get(field).is_string()) Fail(field, "a string");
  }
  void OneOf(const std::string& field, std::initializer_list<const char*> choices) const {
    const json& v = Get(field);
    std::string names;
    for (const char* choice : choices) {
      if (v.is_string() && v.get<std::string>() == choice) return;
      names += names.empty() ? "" : " or ";
      names += choice;
    }
    Fail(field, names);
  }
  void Bool(const std::string& field) const {
    if (!Get(field).is_boolean()) Fail(field, "true or false");
  }
  void Number(const std::string& field) const {
    const json& v = Get(field);
    if (!v.is_number() || !std::isfinite(v.get<double>())) Fail(field, "a finite number");
  }
  void Vector(const std::string& field, size_t n) const {
    if (!IsVector(Get(field), n)) Fail(field, std::to_string(n) + " finite numbers");
  }
  void Matrix(const std::string& field, size_t n) const {
    const json& v = Get(field);
    bool ok = v.is_array() && v.size() == n;
    for (size_t r = 0; ok && r < n; ++r) ok = IsVector(v[r], n);
    if (!ok) Fail(field, "a " + std::to_string(n) + "x" + std::to_string(n) + " matrix of numbers");
  }
  // An array whose every element is checked by `each` (a JsonChecker on the element).
  template <typename Each>
  void Array(const std::string& field, Each each) const {
    const json& v = Get(field);
    if (!v.is_array()) Fail(field, "an array");
    for (size_t k = 0; k < v.size(); ++k)
      each(JsonChecker(source_, v[k], Join(field) + "[" + std::to_string(k) + "]", fix_));
  }
  // An array of [u, v] pairs of finite numbers (pixels); returns its length.
  size_t Pairs(const std::string& field) const {
    const json& v = Get(field);
    if (!v.is_array()) Fail(field, "an array of [u, v] pairs of numbers");
    for (size_t k = 0; k < v.size(); ++k)
      if (!IsVector(v[k], 2))
        Fail(field + "[" + std::to_string(k) + "]", "[u, v]: 2 finite numbers");
    return v.size();
  }
  void Strings(const std::string& field) const {
    Array(field, [](const JsonChecker& c) {
      if (!c.value_.is_string()) c.Fail("", "a string");
    });
  }

 private:
  static bool IsVector(const json& v, size_t n) {
    if (!v.is_array() || v.size() != n) return false;
    for (const json& x : v)
      if (!x.is_number() || !std::isfinite(x.get<double>())) return false;
    return true;
  }
  std::string Join(const std::string& field) const {
    if (field.empty()) return path_.empty() ? "(top level)" : path_;
    return path_.empty() ? field : path_ + "." + field;
  }

  const std::string& source_;
  const json& value_;
  std::string path_;
  const char* fix_;
};

}  // namespace hecal::report
