// .stp: STEP AP214 (ISO 10303-21, schema AUTOMOTIVE_DESIGN): the points as CARTESIAN_POINTs in
// one GEOMETRIC_CURVE_SET of a GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION, with the
// product structure and the mm / radian / uncertainty context a CAD importer needs.
#include "writers.hpp"

namespace imess::exchange::writers {
namespace {

// A STEP string: apostrophes doubled, only printable ASCII.
std::string quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) {
    if (c == '\'') out += "''";
    else if (c >= 0x20 && c < 0x7f && c != '\\') out += c;
  }
  return out + "'";
}


}  // namespace

std::string step(const ExportData& d) {
  const std::string name = quoted(d.file_name);
  std::string out =
      "ISO-10303-21;\nHEADER;\n"
      "FILE_DESCRIPTION(('" + std::to_string(d.points.size()) + " measured points, mm" +
      (d.frame.empty() ? "" : ", frame " + d.frame) + "'),'2;1');\n"
      "FILE_NAME(" + name + ",'" + local_timestamp() + "',('IMESS'),('IMESS'),'" + d.source + "','IMESS','');\n"
      "FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));\nENDSEC;\nDATA;\n"
      "#1=APPLICATION_CONTEXT('core data for automotive mechanical design processes');\n"
      "#2=APPLICATION_PROTOCOL_DEFINITION('international standard','automotive_design',2000,#1);\n"
      "#3=PRODUCT_CONTEXT('',#1,'mechanical');\n"
      "#4=PRODUCT(" + name + "," + name + ",'',(#3));\n"
      "#5=PRODUCT_RELATED_PRODUCT_CATEGORY('part',$,(#4));\n"
      "#6=PRODUCT_DEFINITION_FORMATION('','',#4);\n"
      "#7=PRODUCT_DEFINITION_CONTEXT('part definition',#1,'design');\n"
      "#8=PRODUCT_DEFINITION('design','',#6,#7);\n"
      "#9=PRODUCT_DEFINITION_SHAPE('','',#8);\n"
      "#10=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.));\n"
      "#11=(NAMED_UNIT(*)PLANE_ANGLE_UNIT()SI_UNIT($,.RADIAN.));\n"
      "#12=(NAMED_UNIT(*)SI_UNIT($,.STERADIAN.)SOLID_ANGLE_UNIT());\n"
      "#13=UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.E-07),#10,'distance_accuracy_value','confusion accuracy');\n"
      "#14=(GEOMETRIC_REPRESENTATION_CONTEXT(3)GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((#13))"
      "GLOBAL_UNIT_ASSIGNED_CONTEXT((#10,#11,#12))REPRESENTATION_CONTEXT('Context #1','3D Context with UNIT and UNCERTAINTY'));\n"
      "#15=CARTESIAN_POINT('',(0.,0.,0.));\n"
      "#16=DIRECTION('',(0.,0.,1.));\n"
      "#17=DIRECTION('',(1.,0.,0.));\n"
      "#18=AXIS2_PLACEMENT_3D('',#15,#16,#17);\n";
  int id = 19;
  std::string members;
  for (const auto& p : d.points) {
    out += "#" + std::to_string(id) + "=CARTESIAN_POINT('',(" + real_with_point(p.x(), d.decimals) + "," +
           real_with_point(p.y(), d.decimals) + "," + real_with_point(p.z(), d.decimals) + "));\n";
    members += (members.empty() ? "#" : ",#") + std::to_string(id);
    ++id;
  }
  const int set = id, rep = id + 1;
  out += "#" + std::to_string(set) + "=GEOMETRIC_CURVE_SET('measured points',(" + members + "));\n";
  out += "#" + std::to_string(rep) + "=GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION(" + name + ",(#18,#" +
         std::to_string(set) + "),#14);\n";
  out += "#" + std::to_string(rep + 1) + "=SHAPE_DEFINITION_REPRESENTATION(#9,#" + std::to_string(rep) + ");\n";
  out += "ENDSEC;\nEND-ISO-10303-21;\n";
  return out;
}

}  // namespace imess::exchange::writers
