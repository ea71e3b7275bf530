// Numbers as messcap's reports print them (terminal table, HTML report and its views, the
// qualification): a printf format of one double, and never "-0.0000" — a value that prints as
// zero carries no minus sign (a deviation of -0.00001 mm is 0.0000 at four decimals, not a
// negative one).
#pragma once
#include <string>

namespace imess::messcap {

// `format` takes one double (e.g. "%.4f", "%+.3f").
std::string number_text(double v, const char* format);
// v with `decimals` decimals; `sign`: with a + before a positive value.
std::string fixed_text(double v, int decimals, bool sign = false);

}  // namespace imess::messcap
