#include "scene/loaders/obj/obj_numbers.h"

#include <charconv>
#include <cstdlib>
#include <string>

namespace candela {

namespace {
bool isDigit(char c) { return static_cast<unsigned char>(c - '0') < 10; }
}  // namespace

bool parseObjFloat(std::string_view field, float& value) {
  const char* begin = field.data();
  const char* end = begin + field.size();
  const char* digits = begin < end && (*begin == '+' || *begin == '-') ? begin + 1 : begin;
  if (*begin == '+') ++begin;  // from_chars takes no '+'
  // from_chars would read "inf" and "nan"; a number here starts with a digit or a point.
  if (digits == end || !(isDigit(*digits) || *digits == '.')) return false;
  auto [stop, error] = std::from_chars(begin, end, value);
  if (stop != end) return false;
  if (error == std::errc::result_out_of_range) {
    value = std::strtof(std::string(begin, end).c_str(), nullptr);  // +-HUGE_VALF or 0, as the range requires
    return true;
  }
  return error == std::errc();
}

bool parseObjInteger(std::string_view field, int64_t& value) {
  size_t i = 0;
  bool negative = false;
  if (i < field.size() && (field[i] == '+' || field[i] == '-')) negative = field[i++] == '-';
  if (i == field.size()) return false;
  constexpr int64_t kSaturated = int64_t(1) << 62;
  int64_t magnitude = 0;
  for (; i < field.size(); ++i) {
    if (!isDigit(field[i])) return false;
    magnitude = magnitude >= kSaturated / 10 ? kSaturated : magnitude * 10 + (field[i] - '0');
  }
  value = negative ? -magnitude : magnitude;
  return true;
}

}  // namespace candela
