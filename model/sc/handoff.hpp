// The channel between a unit's setup stage and its walk stage: a set-up triangle waits in the
// setup stage (StHold) until the walk stage is idle; the hand-off cycle h is the first cycle in
// which both hold (docs/timing.md, "Hand-off"). One delta-notified event each way per triangle.
#pragma once
#include <algorithm>
#include <cstdint>
#include <systemc>

namespace trirast::sc {

template <class Txn>
class HandoffPutIf : public virtual sc_core::sc_interface {
 public:
  // Setup side: returns in the hand-off cycle, the triangle loaded into the walk stage.
  virtual void put(Txn* t) = 0;
};

template <class Txn>
class HandoffGetIf : public virtual sc_core::sc_interface {
 public:
  // Walk side: the walk stage is idle from now; returns in the hand-off cycle with the triangle.
  virtual Txn* get() = 0;
};

template <class Txn>
class Handoff : public sc_core::sc_module, public HandoffPutIf<Txn>, public HandoffGetIf<Txn> {
 public:
  explicit Handoff(sc_core::sc_module_name name) : sc_core::sc_module(name) {}

  void put(Txn* t) override {
    while (!walk_idle_) sc_core::wait(idle_ev_);
    walk_idle_ = false;
    slot_ = t;
    loaded_ev_.notify(sc_core::SC_ZERO_TIME);
  }
  Txn* get() override {
    walk_idle_ = true;
    idle_ev_.notify(sc_core::SC_ZERO_TIME);
    while (!slot_) sc_core::wait(loaded_ev_);
    Txn* t = slot_;
    slot_ = nullptr;
    return t;
  }

 private:
  Txn* slot_ = nullptr;
  bool walk_idle_ = false;
  sc_core::sc_event idle_ev_, loaded_ev_;
};

// The improved unit's hand-off as a blocking transport (TLM-2.0 loosely-timed style): the walk
// stage is a target whose load() runs in the caller's process, so a hand-off costs a function
// call instead of two process switches. The cycles are the same as Handoff's: the triangle held
// from cycle s is loaded in h = max(s, first idle cycle of the walk stage).
template <class Txn>
class WalkLoadIf : public virtual sc_core::sc_interface {
 public:
  // The run's first cycle from which the walk stage is idle (0 before the first load).
  virtual uint64_t idle_from() const = 0;
  // Loads the triangle in the run's cycle h (h >= idle_from()) and walks it.
  virtual void load(Txn* t, uint64_t h) = 0;
};

template <class Txn>
class HandoffTransportIf : public virtual sc_core::sc_interface {
 public:
  // Setup side: the triangle waits in StHold from the run's cycle `hold`; returns the hand-off
  // cycle h >= hold, the first cycle the walk stage is idle, in which it was loaded.
  virtual uint64_t put(Txn* t, uint64_t hold) = 0;
  // The first cycle from which the walk stage is idle (after the last put).
  virtual uint64_t walk_idle_from() = 0;
};

template <class Txn>
class HandoffTransport : public sc_core::sc_module, public HandoffTransportIf<Txn> {
 public:
  explicit HandoffTransport(sc_core::sc_module_name name)
      : sc_core::sc_module(name), walk("walk") {}
  sc_core::sc_port<WalkLoadIf<Txn>> walk;

  uint64_t put(Txn* t, uint64_t hold) override {
    const uint64_t h = std::max(hold, walk->idle_from());
    walk->load(t, h);
    return h;
  }
  uint64_t walk_idle_from() override { return walk->idle_from(); }
};

}  // namespace trirast::sc
