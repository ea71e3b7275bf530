// The program file: its text, and its language from --lang or its extension.
#pragma once
#include <optional>
#include <stdexcept>
#include <string>

#include "imess/programs/check.hpp"

namespace imess::messprog {

// A program file that cannot be read; what() names it and why.
struct FileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The whole file. Throws FileError ("cannot read 'part.nc': no such file or directory").
std::string read_program(const std::string& path);

// `forced` (--lang) if given, else from the extension. Throws client::UsageError naming the
// file, its extension and the accepted ones.
programs::Language language_for(const std::string& path, std::optional<programs::Language> forced);

// "part.nc" of "/some/where/part.nc".
std::string base_name(const std::string& path);

}  // namespace imess::messprog
