// docs/tutorial-debugging.md runs as written: every fenced block that starts with `$ tessref` is a
// list of commands (`$ ...` lines), each followed by the output the tutorial shows. The commands
// run from the repository root with this build's tessref, and their output (stdout and stderr)
// must match what is shown, where a line `...` stands for any number of lines left out and
// `[...]` for any text within a line (timings, for instance).
#include <array>
#include <cstdio>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <sys/wait.h>

#include "tests/pipeline/test_util.h"

namespace tessref {
namespace {

struct TutorialCommand {
  int line = 0;         // of the markdown, for messages
  std::string command;  // without "$ "
  std::vector<std::string> expected;
};

// The commands of the markdown's `$ tessref` blocks, in order.
std::vector<TutorialCommand> tutorial_commands(const std::string& markdown) {
  std::vector<TutorialCommand> out;
  std::istringstream in(markdown);
  bool in_fence = false, runnable = false, first = false;
  int n = 0;
  for (std::string line; std::getline(in, line);) {
    ++n;
    if (line.rfind("```", 0) == 0) {
      in_fence = !in_fence;
      runnable = false;
      first = in_fence;
      continue;
    }
    if (!in_fence) continue;
    if (first) runnable = line.rfind("$ tessref ", 0) == 0;
    first = false;
    if (!runnable) continue;
    if (line.rfind("$ ", 0) == 0)
      out.push_back({n, line.substr(2), {}});
    else
      out.back().expected.push_back(line);
  }
  return out;
}

// One expected line as a regex: literal text, `[...]` any text.
std::regex line_pattern(const std::string& expected) {
  static const std::regex special(R"([.^$|()\[\]{}*+?\\])");
  std::string pattern;
  std::size_t from = 0;
  for (std::size_t at; (at = expected.find("[...]", from)) != std::string::npos; from = at + 5)
    pattern += std::regex_replace(expected.substr(from, at - from), special, R"(\$&)") + ".*";
  pattern += std::regex_replace(expected.substr(from), special, R"(\$&)");
  return std::regex(pattern);
}

// Whether `actual` matches `expected` from the given lines on (`...` lines match any run of lines).
bool matches(const std::vector<std::string>& expected, std::size_t e, const std::vector<std::string>& actual,
             std::size_t a) {
  if (e == expected.size()) return a == actual.size();
  if (expected[e] == "...") {
    for (std::size_t skip = a; skip <= actual.size(); ++skip)
      if (matches(expected, e + 1, actual, skip)) return true;
    return false;
  }
  return a < actual.size() && std::regex_match(actual[a], line_pattern(expected[e])) &&
         matches(expected, e + 1, actual, a + 1);
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// Runs a tutorial command from the repository root, `tessref` being this build's binary.
test::CliRun run_from_root(const std::string& command) {
  test::CliRun r;
  const std::string shell = "cd '" + std::string(TESSREF_SOURCE_DIR) + "' && " + test::kBinary +
                            command.substr(std::string("tessref").size()) + " 2>&1";
  FILE* pipe = popen(shell.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf;
  for (std::size_t n; (n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0;) r.output.append(buf.data(), n);
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return r;
}

TEST(TutorialMatcher, ElisionMarkers) {
  const std::vector<std::string> actual = {"a 1.5 ms", "b", "c", "d"};
  EXPECT_TRUE(matches({"a [...] ms", "...", "d"}, 0, actual, 0));
  EXPECT_TRUE(matches({"a [...]", "b", "c", "d", "..."}, 0, actual, 0));
  EXPECT_FALSE(matches({"a [...] ms", "b", "d"}, 0, actual, 0));
  EXPECT_FALSE(matches({"a 1x5 ms", "..."}, 0, actual, 0));  // '.' is literal
  EXPECT_FALSE(matches({"a [...] ms", "b", "c"}, 0, actual, 0));
}

TEST(Tutorial, CommandsRunAsWrittenAndPrintWhatTheTutorialShows) {
  const std::string markdown = test::read_file(std::string(TESSREF_SOURCE_DIR) + "/docs/tutorial-debugging.md");
  const std::vector<TutorialCommand> commands = tutorial_commands(markdown);
  ASSERT_GE(commands.size(), 6u) << "docs/tutorial-debugging.md lost its commands";
  for (const TutorialCommand& c : commands) {
    ASSERT_EQ(c.command.rfind("tessref ", 0), 0u) << "line " << c.line << ": only tessref commands run: " << c.command;
    const test::CliRun r = run_from_root(c.command);
    EXPECT_LT(r.exit_code, 128) << "line " << c.line << ": " << c.command << " crashed\n" << r.output;
    EXPECT_TRUE(matches(c.expected, 0, lines_of(r.output), 0))
        << "docs/tutorial-debugging.md line " << c.line << ": $ " << c.command << "\n--- the tutorial shows:\n"
        << [&] {
             std::string s;
             for (const std::string& l : c.expected) s += l + "\n";
             return s;
           }()
        << "--- it printed:\n" << r.output;
  }
}

}  // namespace
}  // namespace tessref
