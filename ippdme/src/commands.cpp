// Wire names of the command enums.
#include "imess/ippdme/commands.hpp"

namespace imess::ippdme {

std::string_view item_name(Item item) {
  switch (item) {
    case Item::X: return "X";
    case Item::Y: return "Y";
    case Item::Z: return "Z";
    case Item::R: return "R";
    case Item::ToolA: return "Tool.A";
    case Item::ToolB: return "Tool.B";
    case Item::ToolC: return "Tool.C";
    case Item::IJK: return "IJK";
    case Item::ER: return "ER";
    case Item::Q: return "Q";
  }
  return "X";
}

std::string_view coord_system_name(CoordSystem c) {
  switch (c) {
    case CoordSystem::MachineCsy: return "MachineCsy";
    case CoordSystem::MoveableMachineCsy: return "MoveableMachineCsy";
    case CoordSystem::MultipleArmCsy: return "MultipleArmCsy";
    case CoordSystem::PartCsy: return "PartCsy";
  }
  return "MachineCsy";
}

std::string_view csy_target_name(CsyTarget c) {
  switch (c) {
    case CsyTarget::PartCsy: return "PartCsy";
    case CsyTarget::MoveableMachineCsy: return "MoveableMachineCsy";
    case CsyTarget::MultipleArmCsy: return "MultipleArmCsy";
    case CsyTarget::JogDisplayCsy: return "JogDisplayCsy";
    case CsyTarget::JogMoveCsy: return "JogMoveCsy";
    case CsyTarget::SensorCsy: return "SensorCsy";
  }
  return "PartCsy";
}

}  // namespace imess::ippdme
