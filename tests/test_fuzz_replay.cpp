// A fuzz reproducer's replay line runs as written: `trirast fuzz` with an injected
// fault writes reproducers; the "# replay:" line of one, run exactly as written (only `trirast`
// resolved to the binary under test) from the fuzz run's folder, parses every option, finds the
// scene, runs every engine named (the RTL included) and exits with the documented status: 0, as
// the replay has no injected fault. The same line is printed on stderr.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "support/run_command.hpp"

namespace {

using trirast::test::CommandResult;
using trirast::test::run_command;
using trirast::test::TempDir;

const std::string kBin = std::getenv("TRIRAST_TEST_BIN") ? std::getenv("TRIRAST_TEST_BIN") : TRIRAST_BIN;

std::string line_after(const std::string& text, const std::string& tag) {
  const size_t p = text.find(tag);
  if (p == std::string::npos) return "";
  const size_t b = p + tag.size();
  return text.substr(b, text.find('\n', b) - b);
}

TEST(FuzzReplay, ReproducerReplayLineRunsAsWritten) {
  TempDir dir;
  const CommandResult fuzz =
      run_command("cd " + dir.path() + " && mkdir repro && " + kBin +
                  " fuzz --seconds 0 --scenes 4 --seed 7 --max-triangles 40 --out repro"
                  " --inject-fault improved-datapath");
  ASSERT_EQ(fuzz.status, 1) << fuzz.err;  // the injected fault is found
  int replays = 0, with_rtl = 0;
  for (int scene = 0; scene < 4; ++scene) {
    const std::string file = "repro/fuzz-7-" + std::to_string(scene) + ".tri";
    const std::string text = trirast::test::slurp(dir.file(file));
    ASSERT_FALSE(text.empty()) << file << ": " << fuzz.err;
    std::string replay = line_after(text, "# replay: ");
    ASSERT_EQ(replay.rfind("trirast compare --scene " + file + " ", 0), 0u) << replay;
    // The line is printed as it is in the file.
    EXPECT_NE(fuzz.err.find("fuzz: replay: " + replay + "\n"), std::string::npos) << fuzz.err;
    with_rtl += replay.find("improved-rtl") != std::string::npos;
    replay.replace(0, std::string("trirast").size(), kBin);
    const CommandResult r = run_command("cd " + dir.path() + " && " + replay);
    EXPECT_EQ(r.status, 0) << replay << "\n" << r.out << r.err;
    EXPECT_NE(r.out.find("every exact engine agrees with the golden"), std::string::npos) << r.out;
    ++replays;
  }
  EXPECT_EQ(replays, 4);
  EXPECT_GT(with_rtl, 0) << "no replay ran the RTL (pick another seed)";
}

}  // namespace
