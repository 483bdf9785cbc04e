// The channel between a unit's setup stage and its walk stage: a set-up triangle waits in the
// setup stage (StHold) until the walk stage is idle; the hand-off cycle h is the first cycle in
// which both hold (docs/timing.md, "Hand-off"). One delta-notified event each way per triangle.
#pragma once
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

}  // namespace trirast::sc
