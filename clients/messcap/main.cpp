// messcap: the CAD module's successor — captures measured points from messd into a file the
// moment each arrives (open-ended or N), fits / converts point files (`fit`, `convert`) and
// inspects a part by an inspection plan (`inspect`), qualifies the probe on a reference sphere
// (`qualify`).
#include <string_view>

#include "capture_command.hpp"
#include "convert_command.hpp"
#include "fit_command.hpp"
#include "inspect_command.hpp"
#include "qualify_command.hpp"
#include "relate_command.hpp"

int main(int argc, char* argv[]) {
  using namespace imess::messcap;
  const std::string_view command = argc > 1 ? argv[1] : "";
  if (command == "fit") return run_fit_command(argc, argv);
  if (command == "convert") return run_convert_command(argc, argv);
  if (command == "inspect") return run_inspect_command(argc, argv);
  if (command == "relate") return run_relate_command(argc, argv);
  if (command == "qualify") return run_qualify_command(argc, argv);
  return run_capture(argc, argv);
}
