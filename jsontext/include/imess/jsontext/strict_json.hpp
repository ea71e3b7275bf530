// JSON text to a document, strictly: duplicate keys, numbers too large for a double and absurd
// nesting are refused naming the file and the key; syntax errors name line and column.
#pragma once
#include <cstddef>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace imess::jsontext {

// Every refusal; what() is "<source>: ..." — the file, the key and what is accepted.
class JsonTextError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Options {
  bool comments = false;  // "//" and "/* */" comments allowed
  // A number too large for a double (1e400) becomes a string holding its text, so the key's
  // own reader refuses it with the key's range (the configuration does this). Otherwise the
  // number is refused here, naming its key.
  bool overflow_as_text = false;
  std::size_t max_depth = 32;  // objects and arrays nested deeper are refused
  std::string_view depth_hint = "";  // appended to that refusal: what the format needs
};

// Parses `text`, read from `source` (a file name, "<stdin>" ...). Throws JsonTextError.
nlohmann::json parse_strict(std::string_view text, std::string_view source, const Options& options = {});

// A message meant for one reader among several (the web panel's requests): the object it is
// when its text names one of `keys` and it parses strictly as an object holding one of them;
// otherwise nothing, and whoever reads such messages in general refuses it, saying why. The
// text is searched before it is parsed, so messages for other readers cost no parse.
std::optional<nlohmann::json> object_naming(std::string_view message, std::initializer_list<std::string_view> keys,
                                            const Options& options);

}  // namespace imess::jsontext
