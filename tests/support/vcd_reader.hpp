// A VCD file read back for the trace tests: every signal by "scope.name" (its innermost scope),
// each signal's value changes with their times ($dumpvars included), and the helpers the tests
// ask it with (a signal's value at a time, the times a 1-bit signal rises).
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace trirast::test {

struct Vcd {
  std::string top;                           // the outermost scope
  bool timescale_1ns = false;                // "$timescale 1ns $end"
  std::map<std::string, std::string> id_of;  // "scope.name" -> id
  std::map<std::string, int> changes;        // id -> value changes after $dumpvars
  // id -> (time, value) of every change in time order, $dumpvars included; values as written
  // (binary text without the 'b', or one of 0 1 x z).
  std::map<std::string, std::vector<std::pair<uint64_t, std::string>>> values;
  uint64_t first_time = 0, last_time = 0;
};

// A file that cannot be opened fails the test (and reads as empty).
Vcd read_vcd(const std::string& path);

// The value of a signal at time t ("?" before its first value); throws std::out_of_range for a
// signal the file does not have.
std::string value_at(const Vcd& v, const std::string& sig, uint64_t t);

// The times at which a 1-bit signal rises to 1 (its first value included when it is 1).
std::vector<uint64_t> rises(const Vcd& v, const std::string& sig);

// x as VCD binary text (no leading zeros).
std::string vcd_bin(uint64_t x);

}  // namespace trirast::test
