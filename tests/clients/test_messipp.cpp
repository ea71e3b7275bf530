// messipp: the tags it counts (per queue, typed ones kept, open ones skipped), the lines it
// refuses before they go, how it matches the server's lines to what it sent, its command line,
// and the program against a scripted server — the Ack before the next line, the timeout, a
// refused line, a lost link. (--help, exit 1 without messd and exit 2: test_programs.cpp.)
#include <catch2/catch.hpp>

#include <fstream>
#include <thread>

#include "child_process.hpp"
#include "fake_daemon.hpp"
#include "imess/client/usage_error.hpp"
#include "ipp_options.hpp"
#include "tagger.hpp"
#include "transactions.hpp"
#include "typed_line.hpp"

using namespace imess::messipp;
using imess::ippdme::Queue;
using imess::ippdme::Tag;
using imess::ippdme::TagKind;
using imess::test::client_binary;
using imess::test::FakeDaemon;
using imess::test::run_program;
using imess::test::TempDir;
using namespace std::chrono_literals;

namespace {

TypedLine typed(const std::string& line, const Tagger& tagger = {}, bool raw = false) {
  return read_typed_line(line, tagger, {}, raw);
}

IppOptions options(std::initializer_list<const char*> args) {
  std::vector<const char*> argv{"messipp"};
  argv.insert(argv.end(), args.begin(), args.end());
  return parse_ipp_options(static_cast<int>(argv.size()), argv.data());
}

std::string session_file(const TempDir& dir, const std::string& text) {
  const auto path = dir.file("session.txt");
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

}  // namespace

TEST_CASE("messipp tagger: the fast queue's methods take event tags, all others and unknown names command tags") {
  for (const char* fast : {"AbortE()", "GetErrStatusE()", "GetPropE(Tool.Name())", "SetPropE(Tool.GoToPar.Speed(5))",
                           "OnMoveReportE(Time(1), X())"}) {
    INFO(fast);
    CHECK(queue_of(fast) == Queue::Fast);
  }
  for (const char* normal : {"StartSession()", "GoTo(X(10), Y(20))", "GetProp(Tool.Name())", "Get (X())", "Home",
                             "NoSuchMethod(1)", "abortE()", ""}) {
    INFO(normal);
    CHECK(queue_of(normal) == Queue::Normal);
  }
}

TEST_CASE("messipp tagger: each queue counts up on its own from 00001 and E0001") {
  Tagger t;
  std::vector<std::string> got;
  for (const char* call : {"StartSession()", "Get(X())", "GetErrStatusE()", "GoTo(X(1))", "AbortE()", "ClearAllErrors()"}) {
    const Tag tag = t.next(call);
    got.push_back(imess::ippdme::tag_text(tag));
    t.sent(tag);
  }
  CHECK(got == std::vector<std::string>{"00001", "00002", "E0001", "00003", "E0002", "00004"});
  CHECK(t.next("Get(X())") == Tag{TagKind::Command, 5});  // asking uses nothing up
  CHECK(t.next("Get(X())") == Tag{TagKind::Command, 5});
}

TEST_CASE("messipp tagger: a typed tag ahead of the count moves it on, one behind leaves it, open tags are skipped") {
  Tagger t;
  t.sent_typed(Tag{TagKind::Command, 10});
  CHECK(t.next("Get(X())") == Tag{TagKind::Command, 11});
  t.sent_typed(Tag{TagKind::Command, 3});
  CHECK(t.next("Get(X())") == Tag{TagKind::Command, 11});
  CHECK(t.next("AbortE()") == Tag{TagKind::Event, 1});  // the other queue's count is its own
  t.sent_typed(Tag{TagKind::Event, 7});
  CHECK(t.next("AbortE()") == Tag{TagKind::Event, 8});

  const auto open_11_12 = [](Tag tag) { return tag.kind == TagKind::Command && (tag.number == 11 || tag.number == 12); };
  const Tag free = t.next("Get(X())", open_11_12);
  CHECK(free == Tag{TagKind::Command, 13});
  t.sent(free);
  CHECK(t.next("Get(X())") == Tag{TagKind::Command, 14});
}

TEST_CASE("messipp tagger: after 99999 and E9999 the counts start again at 00001 and E0001") {
  Tagger t;
  t.sent_typed(Tag{TagKind::Command, 99999});
  t.sent_typed(Tag{TagKind::Event, 9999});
  CHECK(t.next("Get(X())") == Tag{TagKind::Command, 1});
  CHECK(t.next("AbortE()") == Tag{TagKind::Event, 1});
  const auto all_open = [](Tag) { return true; };  // nothing free: the count's own tag, for the server to refuse
  CHECK(t.next("Get(X())", all_open) == Tag{TagKind::Command, 1});
}

TEST_CASE("messipp: a line that starts with a digit or E and a digit was typed with its tag") {
  for (const char* tagged : {"00001 Get(X())", "E0001 AbortE()", "00000 Get(X())", "1 Get(X())", "00009Get(X())", "E12"}) {
    INFO(tagged);
    CHECK(starts_with_tag(tagged));
  }
  for (const char* bare : {"Get(X())", "EndSession()", "EnumTools()", "E", "", " 00001 Get(X())"}) {
    INFO(bare);
    CHECK_FALSE(starts_with_tag(bare));
  }
}

TEST_CASE("messipp typed lines: tagged, blanks around dropped, typed tags kept, blank lines and quit") {
  Tagger t;
  t.sent(Tag{TagKind::Command, 1});
  auto l = typed("  GoTo(X(10), Y(20))  ", t);
  CHECK(l.action == LineAction::Send);
  CHECK(l.text == "00002 GoTo(X(10), Y(20))");
  CHECK(l.tag == Tag{TagKind::Command, 2});
  CHECK_FALSE(l.typed_tag);

  l = typed("AbortE()", t);
  CHECK(l.text == "E0001 AbortE()");
  CHECK(l.kind == TagKind::Event);

  l = typed("00042 Get(X(), Y(), Z())", t);
  CHECK(l.action == LineAction::Send);
  CHECK(l.text == "00042 Get(X(), Y(), Z())");
  CHECK(l.typed_tag);
  CHECK(l.tag == Tag{TagKind::Command, 42});

  l = typed("E0005 GetPropE(Tool.Name())", t);
  CHECK(l.kind == TagKind::Event);
  CHECK(l.tag == Tag{TagKind::Event, 5});

  CHECK(typed("").action == LineAction::Ignore);
  CHECK(typed(" \t ").action == LineAction::Ignore);
  CHECK(typed("quit").action == LineAction::Quit);
  CHECK(typed(" quit ").action == LineAction::Quit);
  CHECK(typed("quit()").action == LineAction::Refuse);  // a call, and no method of that name
}

TEST_CASE("messipp typed lines: what the parser refuses is not sent, with the error the server would answer") {
  const struct {
    const char* line;
    const char* error;
  } cases[] = {
      {"GetProp(Tool.Name(", R"e(Error(3, 0008, GetProp, "Protocol error"))e"},
      {"home()", R"e(Error(3, 0507, home, "Illegal command"))e"},
      {"Get(X(), W())", R"e(Error(3, 0505, Get, "Argument not recognized"))e"},
      {"ChangeTool(RefTool)", R"e(Error(3, 0502, ChangeTool, "Incorrect arguments"))e"},
      {"00000 Get(X())", R"e(Error(2, 0001, "00000 Get(X())", "Illegal tag"))e"},
      {"00007 AbortE()", R"e(Error(2, 0001, AbortE, "Illegal tag"))e"},  // a fast-queue method with a command tag
      {"00009Get(X())", R"e(Error(2, 0002, "00009Get(X())", "No space at pos. 6"))e"},
  };
  for (const auto& c : cases) {
    INFO(c.line);
    const auto l = typed(c.line);
    CHECK(l.action == LineAction::Refuse);
    CHECK(l.text == c.line);
    CHECK(l.error == c.error);
    CHECK_FALSE(l.tag);
  }
}

TEST_CASE("messipp typed lines: --raw sends what the parser would refuse, tagged all the same") {
  auto l = typed("home()", {}, true);
  CHECK(l.action == LineAction::Send);
  CHECK(l.text == "00001 home()");
  l = typed("NoSuchMethodE()", {}, true);  // unknown: the normal queue, the server answers
  CHECK(l.text == "00001 NoSuchMethodE()");
  l = typed("00000 Get(X())", {}, true);
  CHECK(l.action == LineAction::Send);
  CHECK(l.text == "00000 Get(X())");
  CHECK_FALSE(l.tag);  // not a tag a client may use: no count moves
}

TEST_CASE("messipp transactions: the Ack answers a line, the % completes it, a refusal without Ack ends at its %") {
  Transactions tx;
  CHECK(tx.last_answered());
  CHECK(tx.all_complete());
  tx.sent("00001");
  CHECK_FALSE(tx.last_answered());
  CHECK(tx.is_open("00001"));
  CHECK(tx.received("00001 &"));
  CHECK(tx.last_answered());
  CHECK_FALSE(tx.all_complete());
  tx.sent("00002");
  CHECK(tx.received("00002 ! Error(3, 0008, Get, \"Protocol error\")"));  // refused at once: no Ack, the % follows
  CHECK_FALSE(tx.last_answered());
  CHECK(tx.received("00001 # X(1.0000)"));
  CHECK(tx.open_tags() == std::vector<std::string>{"00001", "00002"});
  CHECK(tx.received("00002 %"));
  CHECK(tx.last_answered());
  CHECK(tx.received("00001 %"));
  CHECK(tx.all_complete());
  CHECK_FALSE(tx.is_open("00001"));
}

TEST_CASE("messipp transactions: a daemon's reports after its % and E0000 events are no answers") {
  Transactions tx;
  tx.sent("E0001");
  CHECK(tx.received("E0001 &"));
  CHECK(tx.received("E0001 %"));
  CHECK(tx.all_complete());
  CHECK_FALSE(tx.received("E0001 # X(430.0000), Y(330.0000), Z(100.0000)"));
  CHECK_FALSE(tx.received("E0000 # KeyPress(\"F1\")"));
  CHECK_FALSE(tx.received("E0000 ! Error(3, 0500, Estop, \"Emergency stop\")"));  // nothing was waiting
  CHECK_FALSE(tx.received(""));
  CHECK_FALSE(tx.received("00001"));
  CHECK(tx.all_complete());
}

TEST_CASE("messipp transactions: a line the server answers on E0000 (its tag unusable) ends there, no % follows") {
  Transactions tx;
  tx.sent("00001");
  CHECK(tx.received("00001 &"));
  tx.sent("00001");  // reused while open
  CHECK_FALSE(tx.last_answered());
  CHECK(tx.received("E0000 ! Error(2, 0001, Get, \"Illegal tag\")"));
  CHECK(tx.last_answered());
  CHECK(tx.open_tags() == std::vector<std::string>{"00001"});  // the first, still waiting for its %
  CHECK(tx.received("00001 %"));
  CHECK(tx.all_complete());
}

TEST_CASE("messipp options: HOST[:PORT] defaults to 127.0.0.1:1294, --raw, --timeout") {
  auto o = options({});
  CHECK(o.endpoint == imess::client::Endpoint{"127.0.0.1", 1294});
  CHECK_FALSE(o.raw);
  CHECK(o.timeout == std::chrono::seconds(30));
  o = options({"cmm", "--raw", "--timeout", "90"});
  CHECK(o.endpoint == imess::client::Endpoint{"cmm", 1294});
  CHECK(o.raw);
  CHECK(o.timeout == std::chrono::seconds(90));
  CHECK(options({"cmm:1300", "--timeout=0.5"}).timeout == std::chrono::milliseconds(500));
  CHECK(options({":1300"}).endpoint == imess::client::Endpoint{"127.0.0.1", 1300});
  CHECK(options({"--timeout", "0"}).timeout.count() == 0);
  CHECK(options({"-h"}).help);
  CHECK_THAT(ipp_usage(), Catch::Contains("usage: messipp [HOST[:PORT]] [--raw] [--timeout S]"));
}

TEST_CASE("messipp options: bad arguments name what was wrong and what is accepted") {
  using imess::client::UsageError;
  CHECK_THROWS_WITH(options({"--verbose"}), Catch::Contains("'--verbose'") && Catch::Contains("--raw, --timeout S, --help"));
  CHECK_THROWS_WITH(options({"--timeout"}), Catch::Contains("--timeout needs a value"));
  CHECK_THROWS_WITH(options({"--timeout", "-1"}), Catch::Contains("'-1'") && Catch::Contains("0..86400"));
  CHECK_THROWS_WITH(options({"--timeout", "5s"}), Catch::Contains("'5s'"));
  CHECK_THROWS_WITH(options({"cmm:0"}), Catch::Contains("'cmm:0'") && Catch::Contains("localhost:1294"));
  CHECK_THROWS_WITH(options({"a", "b"}), Catch::Contains("unexpected argument 'b'"));
}

TEST_CASE("messipp against a scripted server: the Ack before the next line, a command after the %s, CR LF stripped") {
  // StartSession gets no answer until the test sends its Ack; the event-tag line may go then,
  // the command-tag one only after StartSession's %, which comes with the event line's answers.
  FakeDaemon server({0, {}, [](const std::string& line) -> std::vector<std::string> {
                       const std::string tag = line.substr(0, 5);
                       if (tag == "00001") return {};
                       if (tag == "E0001") return {"E0001 &", "E0001 # ErrStatus(0)\r", "E0001 %", "00001 %"};
                       if (tag == "00002") return {"00002 &", "00002 # X(1.0000)", "00002 %"};
                       return {tag + " &", tag + " %"};
                     }});
  TempDir dir;
  const auto in = session_file(dir, "StartSession()\r\nGetErrStatusE()\nGet(X())\n\n00005 EndSession()\nquit\nGet(X())\n");
  imess::test::ChildProcess p({client_binary("messipp"), server.address()}, in);
  REQUIRE(server.wait_for_line("00001 StartSession()"));
  std::this_thread::sleep_for(300ms);
  CHECK(server.received().size() == 1);  // nothing before the Ack
  server.send("00001 &");
  const auto status = p.wait(10s);
  INFO(p.out() << p.err());
  REQUIRE(status);
  CHECK(*status == 0);
  CHECK(p.out() ==
        "> 00001 StartSession()\n00001 &\n"
        "> E0001 GetErrStatusE()\nE0001 &\nE0001 # ErrStatus(0)\nE0001 %\n00001 %\n"
        "> 00002 Get(X())\n00002 &\n00002 # X(1.0000)\n00002 %\n"
        "> 00005 EndSession()\n00005 &\n00005 %\n");
  CHECK(server.received() ==
        std::vector<std::string>{"00001 StartSession()", "E0001 GetErrStatusE()", "00002 Get(X())", "00005 EndSession()"});
  CHECK(p.err().empty());
}

TEST_CASE("messipp against a silent server: no Ack within --timeout is exit 1 naming the open tag, nothing more sent") {
  FakeDaemon server;
  TempDir dir;
  const auto in = session_file(dir, "StartSession()\nGet(X())\n");
  const auto r = run_program({client_binary("messipp"), server.address(), "--timeout", "0.3"}, 10s, in);
  CHECK(r.status == 1);
  CHECK(r.out == "> 00001 StartSession()\n");
  CHECK_THAT(r.err, Catch::Contains("messipp: no answer from " + server.address() + " for 300 ms; still open: 00001 (no Ack yet)"));
  CHECK(server.received() == std::vector<std::string>{"00001 StartSession()"});
}

TEST_CASE("messipp: a refused line is printed instead of sent and the rest goes on, exit 1 says so") {
  FakeDaemon server({0, {}, [](const std::string& line) -> std::vector<std::string> {
                       const std::string tag = line.substr(0, 5);
                       return {tag + " &", tag + " %"};
                     }});
  TempDir dir;
  const auto in = session_file(dir, "StartSession()\nGoTo(X(1)\nEndSession()\n");
  const auto r = run_program({client_binary("messipp"), server.address()}, 10s, in);
  CHECK(r.status == 1);
  CHECK(r.out ==
        "> 00001 StartSession()\n00001 &\n00001 %\n"
        "messipp: not sent: GoTo(X(1) — Error(3, 0008, GoTo, \"Protocol error\")\n"
        "> 00002 EndSession()\n00002 &\n00002 %\n");
  CHECK(r.err == "messipp: 1 line was refused and not sent\n");
}

TEST_CASE("messipp: messd closing the link with a transaction open is exit 1 naming it") {
  FakeDaemon server({0, {}, [](const std::string& line) -> std::vector<std::string> { return {line.substr(0, 5) + " &"}; }});
  TempDir dir;
  const auto in = session_file(dir, "StartSession()\n");
  imess::test::ChildProcess p({client_binary("messipp"), server.address()}, in);
  REQUIRE(p.wait_for_output("00001 &"));
  server.drop_clients();
  REQUIRE(p.wait(5s) == 1);
  CHECK_THAT(p.err(), Catch::Contains("messipp: " + server.address() + ": closed by messd; no end yet to 00001"));
}
