// A Verilated top driven directly by a test program (rtl_assert_demo.cpp,
// rtl_port_precondition.cpp): made with random initial values from seed 1, a 64 x 64 viewport,
// FIFO threshold 8, the sink always ready and the unit's own configuration inputs set by the
// test, then reset as docs/port.md ("Reset") says: rst_ni low for two rising edges with
// tri_valid_i low, released with the clock low. The run's last act is the model's final().
#pragma once

#include <verilated.h>

#include <memory>

namespace trirast::rtl {

template <class Top>
class DirectTop {
 public:
  template <class Configure>
  explicit DirectTop(const Configure& configure) : ctx_(std::make_unique<VerilatedContext>()) {
    ctx_->randReset(2);
    ctx_->randSeed(1);
    top_ = std::make_unique<Top>(ctx_.get(), "top");
    top_->cfg_vp_xmax_i = 63;
    top_->cfg_vp_ymax_i = 63;
    top_->cfg_fifo_depth_i = 8;
    configure(*top_);
    top_->tri_valid_i = 0;
    top_->span_ready_i = 1;
    top_->clk_i = 0;
    top_->rst_ni = 0;
    top_->eval();
    tick();
    tick();
    top_->rst_ni = 1;
    top_->eval();
  }
  ~DirectTop() { top_->final(); }
  DirectTop(const DirectTop&) = delete;
  DirectTop& operator=(const DirectTop&) = delete;

  Top& operator*() { return *top_; }
  Top* operator->() { return top_.get(); }
  // One rising edge, then the clock low again (evaluated).
  void tick() {
    top_->clk_i = 1;
    top_->eval();
    top_->clk_i = 0;
    top_->eval();
  }
  // An assertion or $finish ended the simulation.
  bool finished() const { return ctx_->gotFinish(); }

 private:
  std::unique_ptr<VerilatedContext> ctx_;
  std::unique_ptr<Top> top_;
};

}  // namespace trirast::rtl
