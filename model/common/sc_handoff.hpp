// The channel between a unit's setup stage and its walk stage (docs/timing.md, "Hand-off"): a
// set-up triangle waits in the setup stage (StHold) from cycle `hold` until the walk stage is
// idle; the hand-off cycle h = max(hold, first idle cycle of the walk stage) is the first cycle in
// which both hold, and the walk stage loads the triangle in h.
//
// The hand-off is a blocking transport: the walk stage is a target whose load() runs in the setup
// stage's process, with the cycle passed as an argument, so a hand-off costs a function call
// instead of two process switches and two events.
#pragma once
#include <algorithm>
#include <cstdint>
#include <systemc>

namespace trirast::sc {

// The walk stage's side: the target of the hand-off.
template <class Txn>
class WalkLoadIf : public virtual sc_core::sc_interface {
 public:
  // The run's first cycle from which the walk stage is idle (0 before the first load).
  virtual uint64_t idle_from() const = 0;
  // Loads the triangle in the run's cycle h (h >= idle_from()) and walks it.
  virtual void load(Txn* t, uint64_t h) = 0;
};

// The setup stage's side.
template <class Txn>
class HandoffIf : public virtual sc_core::sc_interface {
 public:
  // The triangle waits in StHold from the run's cycle `hold`; returns the hand-off cycle
  // h >= hold, the first cycle the walk stage is idle, in which it was loaded.
  virtual uint64_t put(Txn* t, uint64_t hold) = 0;
  // The first cycle from which the walk stage is idle (after the last put).
  virtual uint64_t walk_idle_from() = 0;
};

template <class Txn>
class Handoff : public sc_core::sc_module, public HandoffIf<Txn> {
 public:
  explicit Handoff(sc_core::sc_module_name name) : sc_core::sc_module(name), walk("walk") {}
  sc_core::sc_port<WalkLoadIf<Txn>> walk;

  uint64_t put(Txn* t, uint64_t hold) override {
    const uint64_t h = std::max(hold, walk->idle_from());
    walk->load(t, h);
    return h;
  }
  uint64_t walk_idle_from() override { return walk->idle_from(); }
};

}  // namespace trirast::sc
