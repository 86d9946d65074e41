#include "keyword_parsing.h"

#include "error.h"

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace LAMMPS_NS {

namespace {
void refuse(Error *error, const char *style, const char *keyword, const char *expected, const char *text) {
  char msg[512];
  std::snprintf(msg, sizeof(msg), "Illegal %s command: %s expects %s, got '%s'", style, keyword, expected, text);
  error->all(FLERR, msg);
}
}  // namespace

// nan, inf and out-of-range values are refused here, once for every
// keyword of every style (`angle nan` or `youngs_modulus inf` would run).
double parse_number(Error *error, const char *style, const char *keyword, const char *text) {
  char *end = nullptr;
  errno = 0;
  const double value = std::strtod(text, &end);
  if (end == text || *end != '\0') refuse(error, style, keyword, "a number", text);
  if (!std::isfinite(value) || errno == ERANGE) refuse(error, style, keyword, "a finite number", text);
  return value;
}

int parse_integer(Error *error, const char *style, const char *keyword, const char *text) {
  char *end = nullptr;
  errno = 0;
  const long value = std::strtol(text, &end, 10);
  if (end == text || *end != '\0') refuse(error, style, keyword, "an integer", text);
  if (errno == ERANGE || value > INT_MAX || value < INT_MIN)
    refuse(error, style, keyword, "an integer within +-2147483647", text);
  return static_cast<int>(value);
}

bool parse_yes_no(Error *error, const char *style, const char *keyword, const char *text) {
  if (std::strcmp(text, "yes") == 0) return true;
  if (std::strcmp(text, "no") != 0) refuse(error, style, keyword, "yes or no", text);
  return false;
}

}  // namespace LAMMPS_NS
