// JogAction: what an operator asks the jog panel to do, independent of the key that asked.
#pragma once

namespace imess::messjog {

enum class JogAction {
  None,
  XMinus, XPlus, YMinus, YPlus, ZMinus, ZPlus,  // axis jogs
  Stop,
  Speed1, Speed2, Speed3,                       // 2 %, 20 %, 100 %
  Measure,                                      // ForcePt: measure here
  Mark,                                         // remember the current position (client side)
  TowardMark, AwayFromMark,                     // oblique move on the line mark <-> current
  Home,                                         // needs a second press to confirm
  TakeOver,                                     // Take force: needs a second press to confirm
  KeyDone, KeyDel, KeyF1, KeyF2, KeyF3, KeyF4,  // Key <name>: for the I++ DME session that enabled the user
  Quit,
};

}  // namespace imess::messjog
