// `luxel`'s argument parsing in process (cli/command_line.hpp), what the CLI fuzz target drives:
// the README's command lines are accepted; bad ones are refused with exit 2 and one line on stderr
// naming the argument.

#include "command_line.hpp"

#include <gtest/gtest.h>

#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace luxel::cli {
namespace {

struct Parsed {
  std::optional<int> code;
  std::string out, err;
};

Parsed parse(std::vector<std::string> args) {
  args.insert(args.begin(), "luxel");
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  std::ostringstream out, err;
  std::streambuf* cout = std::cout.rdbuf(out.rdbuf());
  std::streambuf* cerr = std::cerr.rdbuf(err.rdbuf());
  CommandLine command_line;
  Parsed parsed;
  parsed.code = command_line.parse(static_cast<int>(argv.size()), argv.data());
  std::cout.rdbuf(cout);
  std::cerr.rdbuf(cerr);
  parsed.out = out.str();
  parsed.err = err.str();
  return parsed;
}

TEST(CommandLine, AcceptsTheReadmesCommands) {
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"render", "--scene", "builtin:demo", "--width", "1280", "--height", "720", "--msaa", "4", "--out", "d.png"},
           {"render", "--scene", "builtin:courtyard", "--model", "ps_2_0", "--bake", "quick", "--stats", "--out", "c.png"},
           {"compare", "--scene", "builtin:courtyard", "--width", "640", "--height", "360", "--out", "cmp"},
           {"grade", "in.png", "out.png", "--lut", "builtin:day-for-night"},
           {"info", "--scene", "builtin:courtyard"},
       }) {
    const Parsed p = parse(args);
    EXPECT_FALSE(p.code.has_value()) << args[0] << ": " << p.err;
    EXPECT_EQ(p.err, "");
  }
}

TEST(CommandLine, HelpGoesToStdoutWithExitZero) {
  const Parsed p = parse({"render", "--help"});
  ASSERT_EQ(p.code, 0);
  EXPECT_NE(p.out.find("--msaa"), std::string::npos);
  EXPECT_EQ(p.err, "");
}

TEST(CommandLine, BadArgumentsAreOneLineNamingThemWithExitTwo) {
  struct Case {
    std::vector<std::string> args;
    std::string names;
  };
  for (const Case& c : std::vector<Case>{{{"render", "--msaa", "3"}, "--msaa"},
                                         {{"render", "--width", "0"}, "--width"},
                                         {{"render", "--height", "100000"}, "--height"},
                                         {{"render", "--width", "nan"}, "--width"},
                                         {{"render", "--model", "ps_1_1"}, "--model"},
                                         {{"render", "--frame", "1", "--frames", "0:3"}, "--frame"},
                                         {{"render", "--bogus"}, "--bogus"},
                                         {{"frobnicate"}, "frobnicate"},
                                         {{}, "subcommand"}}) {
    const Parsed p = parse(c.args);
    SCOPED_TRACE(c.names);
    ASSERT_EQ(p.code, 2);
    ASSERT_FALSE(p.err.empty());
    EXPECT_EQ(p.err.find('\n'), p.err.size() - 1) << p.err;
    EXPECT_EQ(p.err.rfind("luxel", 0), 0u) << p.err;
    EXPECT_NE(p.err.find(c.names), std::string::npos) << p.err;
  }
}

}  // namespace
}  // namespace luxel::cli
