// Escaped XML text for the QIF documents.
#include "qif_xml.hpp"

#include <cmath>
#include <cstdio>

namespace imess::messcap {

std::string xml_escaped(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        if (c < 0x20 && ch != '\t' && ch != '\n' && ch != '\r')
          out += "\xEF\xBF\xBD";
        else
          out += ch;
    }
  }
  return out;
}

std::string qif_number(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  std::string s = buf;
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  if (s == "-0") s = "0";
  return s;
}

std::string qif_vector(const Eigen::Vector3d& v, int decimals) {
  return qif_number(v.x(), decimals) + " " + qif_number(v.y(), decimals) + " " + qif_number(v.z(), decimals);
}

void XmlWriter::start(std::string_view tag, const Attributes& attributes) {
  out_.append(static_cast<std::size_t>(2 * depth_), ' ');
  out_ += '<';
  out_ += tag;
  for (const auto& [name, value] : attributes) out_ += " " + name + "=\"" + xml_escaped(value) + "\"";
}

void XmlWriter::open(std::string_view tag, const Attributes& attributes) {
  start(tag, attributes);
  out_ += ">\n";
  ++depth_;
}

void XmlWriter::close(std::string_view tag) {
  --depth_;
  out_.append(static_cast<std::size_t>(2 * depth_), ' ');
  out_ += "</";
  out_ += tag;
  out_ += ">\n";
}

void XmlWriter::leaf(std::string_view tag, std::string_view text, const Attributes& attributes) {
  start(tag, attributes);
  out_ += '>';
  out_ += xml_escaped(text);
  out_ += "</";
  out_ += tag;
  out_ += ">\n";
}

void XmlWriter::empty(std::string_view tag, const Attributes& attributes) {
  start(tag, attributes);
  out_ += "/>\n";
}

void XmlWriter::ids(std::string_view tag, const std::vector<unsigned>& ids) {
  open(tag, {{"n", std::to_string(ids.size())}});
  for (unsigned id : ids) leaf("Id", std::to_string(id));
  close(tag);
}

}  // namespace imess::messcap
