#pragma once
// What a number is, everywhere pound reads one from people or files (study keys, command-line
// values, lists, distribution arguments, record values): a decimal number with an optional
// sign, decimal point and exponent, such as 16, -0.5, .25, 3., 2.1e9 or 1E-3. Anything else is
// refused rather than guessed: hexadecimal (0x10, which strtod would read as 16), inf, nan,
// thousands separators, trailing text (12kg, 1e), an empty field, and a value beyond the
// range of a double.
#include <string>

namespace pound {

/// The valid form, for error messages: "a decimal number such as 16, -0.5 or 2.1e9".
extern const char* const kNumberForm;

/// True when `text` (no surrounding white space) is a decimal number as above whose value is
/// finite; the value is stored in *value. False otherwise (*value untouched).
bool read_decimal(const std::string& text, double* value);

/// Reads a decimal number that starts at text[pos] after any blanks and is not followed by a
/// digit, '.', 'x' or 'X' (so 0x10 and 1.2.3 are refused, ".0050 SEC" and "5590," are read):
/// the header fields of record files ("NPTS=  5590, DT=   .0050 SEC"). False when there is
/// no such number there.
bool read_decimal_at(const std::string& text, std::size_t pos, double* value);

/// True when `text` names a non-finite value (nan, inf, infinity, with any sign and case):
/// errors then say "not finite" instead of "not a number".
bool names_non_finite(const std::string& text);

}  // namespace pound
