// The generic machine of messprog check and plot.
#include "offline_machine.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "imess/client/usage_error.hpp"
#include "number_text.hpp"

namespace imess::messprog {
namespace {

using client::UsageError;
using programs::Language;

int index_of(const planner::Machine& m, char letter) {
  for (int i = 0; i < m.count; ++i)
    if (m.axes[i].letter == letter) return i;
  return -1;
}


}  // namespace

std::string default_letters(Language lang) { return lang == Language::Mrm ? "XYCUV" : "XYZ"; }

planner::Machine offline_machine(Language lang, const OfflineSpec& spec) {
  const std::string letters = spec.letters.empty() ? default_letters(lang) : spec.letters;
  const std::string accepted = "; accepted: 1 to 9 axis letters of X Y Z A B C U V W, each once (e.g. XYZ, XYZC, XYCUV)";
  if (letters.empty() || letters.size() > static_cast<std::size_t>(planner::kMaxAxes))
    throw UsageError("--axes '" + letters + "': " + std::to_string(letters.size()) + " letters" + accepted);
  for (std::size_t i = 0; i < letters.size(); ++i) {
    const char c = letters[i];
    if (std::find(planner::kAxisLetters.begin(), planner::kAxisLetters.end(), c) == planner::kAxisLetters.end())
      throw UsageError("--axes '" + letters + "': '" + std::string(1, c) + "' is no axis letter" + accepted);
    if (letters.find(c) != i)
      throw UsageError("--axes '" + letters + "': " + std::string(1, c) + " appears twice" + accepted);
  }
  if (!(spec.travel_min < spec.travel_max) || !std::isfinite(spec.travel_min) || !std::isfinite(spec.travel_max))
    throw UsageError("--travel " + number_text(spec.travel_min) + ":" + number_text(spec.travel_max) +
                     ": accepted MIN:MAX with MIN < MAX (mm, degrees for rotary axes), e.g. -500:500");
  planner::Machine m = planner::make_machine(letters.c_str(), spec.travel_min, spec.travel_max,
                                             kOfflineMaxVelocity, kOfflineMaxAccel);
  if (lang == Language::Hpgl && (index_of(m, 'X') < 0 || index_of(m, 'Y') < 0))
    throw UsageError("--axes '" + letters + "': HPGL draws in X and Y; accepted: letters including X and Y (and Z for the pen)");
  // The arm: X and Y its linear base, every other axis a rotary joint (the MRM words A B C
  // move the rotary axes in order, as on config/sim-mrm-arm.json).
  if (lang == Language::Mrm)
    for (int i = 0; i < m.count; ++i)
      if (m.axes[i].letter != 'X' && m.axes[i].letter != 'Y') m.axes[i].kind = planner::AxisKind::Rotary;
  return m;
}

programs::Setup offline_setup(const planner::Machine& machine) {
  programs::Setup s;
  s.machine = machine;
  for (int i = 0; i < machine.count; ++i)
    s.start[i] = std::clamp(0.0, machine.axes[i].travel_min, machine.axes[i].travel_max);
  // MRM A B C: the machine's rotary axes in order (MrmOptions' default; on XYCUV A → C, B → U, C → V).
  if (index_of(machine, 'Z') < 0) s.hpgl.pen = programs::HpglOptions::Pen::Output;
  return s;
}

std::string describe_machine(const planner::Machine& machine, const programs::Setup& setup) {
  std::string letters, rotary, start;
  bool at_zero = true;
  for (int i = 0; i < machine.count; ++i) {
    letters += machine.axes[i].letter;
    if (machine.axes[i].kind == planner::AxisKind::Rotary) rotary += std::string(rotary.empty() ? "" : " ") + machine.axes[i].letter;
    at_zero = at_zero && setup.start[i] == 0;
    start += std::string(i ? " " : "") + number_text(setup.start[i]);
  }
  const auto& a = machine.axes[0];
  std::string text = "axes " + letters + ", travel " + number_text(a.travel_min) + ".." + number_text(a.travel_max) + ", " +
                     number_text(a.max_velocity) + " mm/s and " + number_text(a.max_accel) + " mm/s² per axis";
  if (!rotary.empty()) text += " (degrees for " + rotary + ")";
  text += at_zero ? ", starting at 0" : ", starting at " + start;
  return text;
}

}  // namespace imess::messprog
