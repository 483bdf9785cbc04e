#include "improved2/improved2_direct_test_2x2.hpp"

namespace trirast {

Improved2DirectTestOut Improved2DirectTest2x2::run(const BoxStageOut& box) {
  // covered[j][i]: all three edges pass at centre (i, j) of the box.
  bool covered[2][2];
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      bool in = i <= box.Xmax && j <= box.Ymax;
      for (int k = 0; k < 3 && in; ++k) {
        const BoxStageEdge& e = box.edge[k];
        in = e.E_L + (i ? e.a : 0) + (j ? e.b : 0) >= 0;
      }
      covered[j][i] = in;
    }
  Improved2DirectTestOut out{};
  for (int j = 0; j < 2; ++j) {
    out.valid[j] = covered[j][0] || covered[j][1];
    out.begin[j] = covered[j][0] ? 0 : 1;
    out.end[j] = covered[j][1] ? 2 : 1;
  }
  return out;
}

}  // namespace trirast
