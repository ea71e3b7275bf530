// Tools and properties: the path grammar of GetProp / SetProp / EnumProp over the active tool
// and FoundTool (docs/ippdme.md, "Tools and properties").
#include "imess/ippdme/tools.hpp"

#include <algorithm>
#include <iterator>
#include <stdexcept>

namespace imess::ippdme {

namespace {

constexpr std::string_view kBlocks[] = {"GoToPar",   "GoToPar",   "PtMeasPar", "PtMeasPar", "PtMeasPar",
                                        "PtMeasPar", "PtMeasPar", "ScanPar",   "ScanPar",   "ScanPar"};
constexpr std::string_view kNames[] = {"Speed",  "Accel",   "Speed", "Accel", "Approach",
                                       "Search", "Retract", "Speed", "Accel", "Retract"};
static_assert(std::size(kBlocks) == kParamCount && std::size(kNames) == kParamCount);
constexpr std::string_view kBlockOrder[] = {"GoToPar", "PtMeasPar", "ScanPar"};
constexpr std::string_view kLimits[] = {"Min", "Max", "Act", "Def"};

std::vector<std::string_view> split(std::string_view path) {
  std::vector<std::string_view> parts;
  while (true) {
    const auto dot = path.find('.');
    parts.push_back(path.substr(0, dot));
    if (dot == std::string_view::npos) return parts;
    path.remove_prefix(dot + 1);
  }
}

std::optional<Param> param_of(std::string_view block, std::string_view name) {
  for (int i = 0; i < kParamCount; ++i)
    if (kBlocks[i] == block && kNames[i] == name) return static_cast<Param>(i);
  return std::nullopt;
}

bool is_block(std::string_view s) { return s == "GoToPar" || s == "PtMeasPar" || s == "ScanPar"; }
// The blocks of a measuring tool: NoTool has none (1503).
bool probing_block(std::string_view s) { return s == "PtMeasPar" || s == "ScanPar"; }

PropertyResult error(ErrorCode code) { return {std::nullopt, code, false}; }

}  // namespace

std::string_view block_name(Param p) { return kBlocks[static_cast<int>(p)]; }
std::string_view param_name(Param p) { return kNames[static_cast<int>(p)]; }

ToolBox::ToolBox(std::vector<ToolSpec> tools) : tools_(std::move(tools)) {
  if (tools_.empty()) throw std::invalid_argument("at least one tool is needed");
  for (std::size_t i = 0; i < tools_.size(); ++i) {
    const auto& t = tools_[i];
    if (t.name.empty() || !is_name(t.name) || t.name.find('.') != std::string::npos)
      throw std::invalid_argument("tool name '" + t.name + "': letters and digits, starting with a letter");
    if (t.name == kNoTool || t.name == kUnDefTool || t.name == kBaseTool)
      throw std::invalid_argument("tool name '" + t.name + "' is reserved (NoTool, UnDefTool, BaseTool)");
    for (std::size_t j = 0; j < i; ++j)
      if (tools_[j].name == t.name) throw std::invalid_argument("tool name '" + t.name + "' is given twice");
    for (int p = 0; p < kParamCount; ++p) {
      const Range& r = t.params[p];
      if (!(r.min <= r.def && r.def <= r.max))
        throw std::invalid_argument("tool '" + t.name + "': " + std::string(kBlocks[p]) + "." + std::string(kNames[p]) +
                                    " needs Min <= Def <= Max");
    }
  }
  ToolSpec none = tools_.front();
  none.name = std::string(kNoTool);
  none.radius = 0;
  none.measures = false;
  ToolSpec base = none;
  base.name = std::string(kBaseTool);
  base.measures = true;  // its probing values are the machine's; it is never active
  tools_.push_back(std::move(none));
  tools_.push_back(std::move(base));
  acts_.resize(tools_.size());
  for (std::size_t i = 0; i < tools_.size(); ++i)
    for (int p = 0; p < kParamCount; ++p) acts_[i][p] = tools_[i].params[p].def;
  change(tools_.front().name);
}

int ToolBox::find(std::string_view name) const {
  for (std::size_t i = 0; i + 1 < tools_.size(); ++i)
    if (tools_[i].name == name) return static_cast<int>(i);
  return -1;
}

std::vector<std::string> ToolBox::names() const {
  std::vector<std::string> out;
  for (std::size_t i = 0; i + 1 < tools_.size(); ++i) out.push_back(tools_[i].name);
  return out;
}

bool ToolBox::change(std::string_view name) {
  active_ = find(name);
  if (active_ < 0) return false;
  last_active_ = active_;
  for (int p = 0; p < kParamCount; ++p) acts_[active_][p] = tools_[active_].params[p].def;  // the spec: Def on a change
  return true;
}

double ToolBox::lowered(Param p) const {
  const int i = active_ < 0 ? last_active_ : active_;
  const double a = acts_[i][static_cast<int>(p)];
  return a < tools_[i].params[static_cast<int>(p)].max ? a : 0;
}

bool ToolBox::find_tool(std::string_view name) {
  const int i = name == kBaseTool ? base() : find(name);
  if (i < 0) return false;
  found_ = i;
  return true;
}

PropertyResult ToolBox::get(std::string_view path) const {
  const auto parts = split(path);
  const bool tool = parts[0] == "Tool";
  if (!tool && parts[0] != "FoundTool") return error(ErrorCode::BadProperty);
  const int index = tool ? active_ : found_;
  if (index < 0) return error(ErrorCode::ToolNotDefined);  // UnDefTool has no properties
  const ToolSpec& t = tools_[index];
  if (parts.size() == 2 && parts[1] == "Name") return {Value::call(path, {Value::of_string(t.name)}), std::nullopt, false};
  if (parts.size() < 3 || parts.size() > 4) return error(ErrorCode::BadProperty);
  const auto p = param_of(parts[1], parts[2]);
  if (!p) return error(ErrorCode::BadProperty);
  if (!t.measures && probing_block(parts[1])) return error(ErrorCode::ToolNotDefined);  // NoTool has no probing values
  const Range& r = t.params[static_cast<int>(*p)];
  double v = acts_[index][static_cast<int>(*p)];
  if (parts.size() == 4) {
    if (parts[3] == "Min") v = r.min;
    else if (parts[3] == "Max") v = r.max;
    else if (parts[3] == "Def") v = r.def;
    else if (parts[3] != "Act") return error(ErrorCode::BadProperty);
  }
  return {Value::call(path, {Value::of_number(v)}), std::nullopt, false};
}

PropertyResult ToolBox::set(std::string_view path, double value) {
  const auto parts = split(path);
  const bool tool = parts[0] == "Tool";
  if (!tool && parts[0] != "FoundTool") return error(ErrorCode::BadProperty);
  const int index = tool ? active_ : found_;
  if (index < 0) return error(ErrorCode::ToolNotDefined);
  const ToolSpec& t = tools_[index];
  if (parts.size() == 2 && parts[1] == "Name") return error(ErrorCode::BadArgument);  // read only
  if (parts.size() < 3 || parts.size() > 4) return error(ErrorCode::BadProperty);
  const auto p = param_of(parts[1], parts[2]);
  if (!p) return error(ErrorCode::BadProperty);
  if (parts.size() == 4 && parts[3] != "Act") {
    const bool limit = parts[3] == "Min" || parts[3] == "Max" || parts[3] == "Def";
    return error(limit ? ErrorCode::BadArgument : ErrorCode::BadProperty);  // a limit is read only
  }
  if (!t.measures && probing_block(parts[1])) return error(ErrorCode::ToolNotDefined);
  const Range& r = t.params[static_cast<int>(*p)];
  const double kept = std::clamp(value, r.min, r.max);
  acts_[index][static_cast<int>(*p)] = kept;
  return {std::nullopt, kept != value ? std::optional(ErrorCode::ArgumentOutOfRange) : std::nullopt, kept != value};
}

std::optional<std::vector<PropertyEntry>> ToolBox::enumerate(std::string_view path, bool recursive, ErrorCode& err) const {
  const auto parts = split(path);
  const bool tool = parts[0] == "Tool";
  err = ErrorCode::BadProperty;
  if ((!tool && parts[0] != "FoundTool") || parts.size() > 3) return std::nullopt;
  const int index = tool ? active_ : found_;
  if (index < 0) {
    err = ErrorCode::ToolNotDefined;
    return std::nullopt;
  }
  const ToolSpec& t = tools_[index];
  std::vector<PropertyEntry> out;
  // A value's children: Min, Max, Act, Def.
  auto value_entries = [&](const std::string& prefix, std::string_view name) {
    out.emplace_back(prefix + std::string(name), "Number");
    if (recursive)
      for (auto l : kLimits) out.emplace_back(prefix + std::string(name) + "." + std::string(l), "Number");
  };
  auto block_entries = [&](const std::string& prefix, std::string_view block) {
    for (int p = 0; p < kParamCount; ++p)
      if (kBlocks[p] == block) value_entries(prefix, kNames[p]);
  };
  if (parts.size() == 1) {
    out.emplace_back("Name", "String");
    for (std::string_view block : kBlockOrder) {
      if (!t.measures && probing_block(block)) continue;
      out.emplace_back(std::string(block), "Property");
      if (recursive) block_entries(std::string(block) + ".", block);
    }
    return out;
  }
  if (!is_block(parts[1])) return std::nullopt;
  if (!t.measures && probing_block(parts[1])) {
    err = ErrorCode::ToolNotDefined;
    return std::nullopt;
  }
  if (parts.size() == 2) {
    block_entries("", parts[1]);
    return out;
  }
  if (!param_of(parts[1], parts[2])) return std::nullopt;
  for (auto l : kLimits) out.emplace_back(std::string(l), "Number");
  return out;
}

}  // namespace imess::ippdme
