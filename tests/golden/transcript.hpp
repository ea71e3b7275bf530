// A golden transcript as text and as entries: what the test sends and waits (inputs, kept on
// regeneration) and what messd answered (observed, rewritten). Format: tests/golden/README.md.
#pragma once
#include <string>
#include <vector>

namespace imess::golden {

enum class EntryKind {
  Comment,   // "# ..." or a blank line
  Config,    // "@ config/x.json": the configuration, relative to the source tree
  Connect,   // "+2" or "+2 127.0.0.2": client 2 connects (from that address)
  Close,     // "-2": client 2 closes its end
  Send,      // "> line" / "2> line": one line sent (escapes: \xHH, \\); ">>": in the same step
            // as the line before (one write, before the machine runs)
  Advance,   // "= 500 ms": the machine runs that long in virtual time
  Receive,   // "< line" / "2< line": one line received (observed)
  Time,      // "~ 1234 ms": virtual time when the following lines arrived (observed)
};

struct Entry {
  EntryKind kind;
  int client = 1;    // Connect, Close, Send, Receive
  std::string text;  // Comment: whole line; Config: path; Connect: address; Send/Receive: the bytes
  long ms = 0;       // Advance, Time
  bool joined = false;  // Send: sent together with the Send before it
};

// Parses a transcript; throws std::runtime_error naming the line for anything else.
std::vector<Entry> parse_transcript(const std::string& text, const std::string& name);
// The text of entries, one line each; parse_transcript(format_transcript(e)) == e.
std::string format_transcript(const std::vector<Entry>& entries);
// Whether the entry is observed (rewritten on regeneration) rather than an input.
bool observed(const Entry& e);

// Bytes <-> the escaped form of a line: \xHH for bytes outside printable ASCII, \\ for "\".
std::string escape_line(const std::string& bytes);
std::string unescape_line(const std::string& text, const std::string& where);

}  // namespace imess::golden
