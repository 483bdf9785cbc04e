#include "vcd_reader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace trirast::test {

Vcd read_vcd(const std::string& path) {
  Vcd v;
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << "cannot read " << path;
  std::string line;
  std::vector<std::string> scopes;
  uint64_t t = 0;
  bool dump = false, seen_time = false, in_timescale = false;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string w;
    ls >> w;
    if (w == "$timescale") {
      std::string unit;
      ls >> unit;
      in_timescale = unit.empty();  // the unit on the next line
      if (unit == "1ns") v.timescale_1ns = true;
    } else if (in_timescale) {
      if (w == "1ns") v.timescale_1ns = true;
      in_timescale = false;
    } else if (w == "$scope") {
      std::string kind, name;
      ls >> kind >> name;
      if (scopes.empty() && v.top.empty()) v.top = name;
      scopes.push_back(name);
    } else if (w == "$upscope") {
      if (!scopes.empty()) scopes.pop_back();
    } else if (w == "$var") {
      std::string type, width, id, name;
      ls >> type >> width >> id >> name;
      v.id_of[(scopes.empty() ? std::string() : scopes.back()) + "." + name] = id;
    } else if (w == "$dumpvars") {
      dump = true;
    } else if (w == "$end") {
      dump = false;
    } else if (!w.empty() && w[0] == '#') {
      t = std::stoull(w.substr(1));
      if (!seen_time) v.first_time = t;
      seen_time = true;
      v.last_time = t;
    } else if (!w.empty() &&
               (w[0] == 'b' || w[0] == '0' || w[0] == '1' || w[0] == 'x' || w[0] == 'z')) {
      std::string id, val;
      if (w[0] == 'b') {
        val = w.substr(1);
        ls >> id;
      } else {
        val = w.substr(0, 1);
        id = w.substr(1);
      }
      v.values[id].push_back({t, val});
      if (!dump) ++v.changes[id];
    }
  }
  return v;
}

std::string value_at(const Vcd& v, const std::string& sig, uint64_t t) {
  const auto& ch = v.values.at(v.id_of.at(sig));
  const auto it = std::upper_bound(ch.begin(), ch.end(), t,
                                   [](uint64_t x, const auto& tv) { return x < tv.first; });
  return it == ch.begin() ? "?" : std::prev(it)->second;
}

std::vector<uint64_t> rises(const Vcd& v, const std::string& sig) {
  std::vector<uint64_t> r;
  std::string prev = "?";
  for (const auto& tv : v.values.at(v.id_of.at(sig))) {
    if (tv.second == "1" && prev != "1") r.push_back(tv.first);
    prev = tv.second;
  }
  return r;
}

std::string vcd_bin(uint64_t x) {
  std::string s;
  do {
    s.insert(s.begin(), char('0' + (x & 1)));
    x >>= 1;
  } while (x);
  return s;
}

}  // namespace trirast::test
