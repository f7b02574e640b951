#pragma once
#include <cstdint>
#include <string_view>

namespace candela {

// A whole OBJ field as a decimal number: an optional sign, digits with an optional point, an optional exponent
// ("-1.5", ".5", "+2", "1e-3"). "nan", "inf", hexadecimal and trailing characters are not numbers. Values past
// float's range become +-infinity (or 0 below it), which the caller rejects as non-finite.
bool parseObjFloat(std::string_view field, float& value);

// A whole OBJ field as a decimal integer with an optional sign. Magnitudes past 2^62 saturate, so that they read
// as out of range rather than wrapping.
bool parseObjInteger(std::string_view field, int64_t& value);

}  // namespace candela
