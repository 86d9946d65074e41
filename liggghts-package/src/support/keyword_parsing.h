/* ----------------------------------------------------------------------
   hsrod - strict parsing of keyword values for the package's styles: a value
   that is not entirely a number (or yes/no) stops the run with
   "Illegal <style> command: <keyword> expects ..., got '<text>'".
------------------------------------------------------------------------- */

#ifndef HSROD_KEYWORD_PARSING_H
#define HSROD_KEYWORD_PARSING_H

namespace LAMMPS_NS {

class Error;

// `style` names the command or style in the message, e.g. "fix rod/bonds".
double parse_number(Error *error, const char *style, const char *keyword, const char *text);
int parse_integer(Error *error, const char *style, const char *keyword, const char *text);
bool parse_yes_no(Error *error, const char *style, const char *keyword, const char *text);

}  // namespace LAMMPS_NS

#endif
