// What `messprog run` sends after `Upload <name>`: the program's lines as they are, checked
// before connecting against what the wire can carry (docs/prog-protocol: a line of only "."
// ends the upload; at most 1 000 000 lines and 16 MiB; protocol lines of at most 200
// characters without CR, NUL or 0xFF).
#pragma once
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "imess/programs/check.hpp"

namespace imess::messprog {

inline constexpr std::size_t kMaxUploadLines = 1'000'000;
inline constexpr std::size_t kMaxUploadBytes = 16u << 20;

// A program the wire cannot carry; what() is "FILE:LINE: what, accepted ...".
struct UploadError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Upload {
  std::string name;                // the name messd files it under
  std::vector<std::string> lines;  // without terminators (a CR before LF removed)
};

// The name on messd: FILE's base name with characters other than letters, digits and
// . _ - + replaced by '_' (the protocol separates words by blanks); when its extension does
// not give `lang` (a file read with --lang), the language's extension is appended
// ("part.txt" → "part.txt.nc").
std::string upload_name(const std::string& path, programs::Language lang);

// Throws UploadError naming the first line the wire cannot carry.
Upload prepare_upload(const std::string& path, std::string_view text, programs::Language lang);

}  // namespace imess::messprog
