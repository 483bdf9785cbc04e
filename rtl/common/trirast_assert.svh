// Assertion macros of the RTL (as Ibex's prim_assert.sv): a module includes this header and
// writes its protocol assumptions beside the logic they guard.
//
//   `ASSERT(Name, Prop, Clk, Rst)        Prop holds at every rising edge of Clk while Rst is 0
//                                        (Rst is the "in reset" condition, e.g. !rst_ni); Prop
//                                        is a plain expression ($past allowed, no |-> or |=>)
//   `ASSERT_IMPLIES(Name, Ante, Cons, Clk, Rst)
//                                        Ante |-> Cons: in a cycle with Ante, Cons
//   `ASSERT_IF(Name, Cond, Prop, Clk, Rst)
//                                        Cond |-> Prop with Prop evaluated only in the cycles
//                                        with Cond (no $past in it): for an expensive Prop
//   `ASSERT_NEXT(Name, Ante, Cons, Clk, Rst)
//                                        Ante |=> Cons: in the cycle after one with Ante (out of
//                                        reset), Cons
//   `ASSERT_KNOWN(Name, Sig, Clk, Rst)   Sig has no X or Z bit at every such edge
//   `ASSERT_KNOWN_IF(Name, Cond, Sig, Clk, Rst)
//                                        ... in the cycles with Cond
//   `ASSERT_STABLE(Name, Wait, Data, Clk, Rst)
//                                        a handshake's data held: after a cycle with Wait (valid
//                                        and not ready), Data equals its value of that cycle
//                                        (Wait |=> $stable(Data)), checked at every such edge
//   `ASSERT_INIT(Name, Prop)             Prop (on parameters) holds at time zero
//
// Three expansions:
//  - Verilator (simulation): concurrent assertions; a failure prints "[ASSERT FAILED] [instance]
//    Name" through $error, which stops a Verilated model (--assert) with a non-zero exit.
//  - FORMAL (Yosys's read_verilog -formal defines it; tb/formal/, docs/formal.md): immediate
//    assertions in an always @(posedge Clk) block, enabled out of reset, which the formal proofs
//    check with their own properties. Yosys 0.23 parses no |->, |=> or concurrent assertion, so
//    ASSERT_IMPLIES is !Ante || Cons, ASSERT_NEXT a register of Ante (out of reset) and Cons
//    asserted the cycle after, ASSERT_STABLE a copy of Data compared the cycle after a Wait, and
//    ASSERT_INIT an assertion on the parameters in every cycle. ASSERT_KNOWN and
//    ASSERT_KNOWN_IF expand to nothing: a formal model has two-valued bits (an undriven or
//    unreset bit is a free 0 or 1 the solver chooses), so no bit is ever X.
//  - anything else (synthesis, Yosys without -formal, Icarus 11: "sorry:
//    concurrent_assertion_item not supported"): nothing, so the synthesized netlists do not
//    depend on the assertions.
// Every argument must be given (no defaults: the empty forms take the same arguments); a
// concatenation ({a, b}) is one argument in all three tools.
`ifndef TRIRAST_ASSERT_SVH
`define TRIRAST_ASSERT_SVH

`ifdef VERILATOR
`define TRIRAST_ASSERTIONS_ON
`endif

`ifdef FORMAL

// The assertions carry no label: Yosys 0.23 names a labelled procedural assertion without its
// generate scope (two in a generate loop collide), so a failure names the RTL's file and line.
`define ASSERT(__name, __prop, __clk, __rst)                                    \
  always @(posedge __clk) if (!(__rst)) assert (__prop);

`define ASSERT_IMPLIES(__name, __ante, __cons, __clk, __rst)                    \
  always @(posedge __clk) if (!(__rst)) assert (!(__ante) || (__cons));

`define ASSERT_IF(__name, __cond, __prop, __clk, __rst)                         \
  `ASSERT_IMPLIES(__name, __cond, __prop, __clk, __rst)

`define ASSERT_NEXT(__name, __ante, __cons, __clk, __rst)                       \
  logic __name``_ante_q;                                                          \
  always @(posedge __clk) begin                                                   \
    if (!(__rst) && __name``_ante_q) assert (__cons);                    \
    __name``_ante_q <= !(__rst) && (__ante);                                      \
  end

`define ASSERT_KNOWN(__name, __sig, __clk, __rst)
`define ASSERT_KNOWN_IF(__name, __cond, __sig, __clk, __rst)

`define ASSERT_STABLE(__name, __wait, __data, __clk, __rst)                      \
  logic __name``_wait_q;                                                          \
  logic [$bits(__data)-1:0] __name``_data_q;                                      \
  always @(posedge __clk) begin                                                   \
    if (!(__rst) && __name``_wait_q) assert ((__data) == __name``_data_q); \
    __name``_data_q <= (__data);                                                  \
    __name``_wait_q <= !(__rst) && (__wait);                                      \
  end

`define ASSERT_INIT(__name, __prop)                                             \
  always @* assert (__prop);

`elsif TRIRAST_ASSERTIONS_ON

`define ASSERT(__name, __prop, __clk, __rst)                                    \
  /* verilator lint_off SYNCASYNCNET */                                          \
  __name: assert property (@(posedge __clk) disable iff (__rst) (__prop))        \
    else $error("[ASSERT FAILED] [%m] %s", `"__name`");                          \
  /* verilator lint_on SYNCASYNCNET */

`define ASSERT_IMPLIES(__name, __ante, __cons, __clk, __rst)                    \
  `ASSERT(__name, (__ante) |-> (__cons), __clk, __rst)

// ASSERT_IMPLIES for an expensive Cons of no $past: an immediate assertion in a clocked block, so
// Cons is evaluated only at the edges where Cond holds (Verilator evaluates a concurrent
// property's consequent at every edge; the triangle port's checks, products of the vertices, are
// the case).
`define ASSERT_IF(__name, __cond, __prop, __clk, __rst)                         \
  /* verilator lint_off SYNCASYNCNET */                                          \
  always_ff @(posedge __clk) begin                                                \
    if (!(__rst) && (__cond)) begin                                               \
      __name: assert (__prop) else $error("[ASSERT FAILED] [%m] %s", `"__name`"); \
    end                                                                           \
  end                                                                             \
  /* verilator lint_on SYNCASYNCNET */

`define ASSERT_NEXT(__name, __ante, __cons, __clk, __rst)                       \
  `ASSERT(__name, (__ante) |=> (__cons), __clk, __rst)

`define ASSERT_KNOWN(__name, __sig, __clk, __rst)                               \
  `ASSERT(__name, !$isunknown(__sig), __clk, __rst)

`define ASSERT_KNOWN_IF(__name, __cond, __sig, __clk, __rst)                    \
  `ASSERT(__name, (__cond) |-> !$isunknown(__sig), __clk, __rst)

// Wait |=> $stable(Data) written for simulation speed: a concurrent $stable keeps a sampled copy
// of every bit of Data at every evaluation of the Verilated model (the improved unit's triangle,
// hand-off and span data cost about 590 more instructions per simulated cycle that way, an
// eighth of its simulation; docs/rtl.md), so here a copy is taken in the cycle a wait begins and
// an immediate assertion compares Data with it while the wait lasts. The copy is simulation-only
// logic.
`define ASSERT_STABLE(__name, __wait, __data, __clk, __rst)                      \
  logic __name``_wait_q;                                                          \
  logic [$bits(__data)-1:0] __name``_data_q;                                      \
  /* verilator lint_off SYNCASYNCNET */                                          \
  always_ff @(posedge __clk) begin                                                \
    if (!(__rst) && __name``_wait_q) begin                                        \
      __name: assert ((__data) == __name``_data_q)                               \
        else $error("[ASSERT FAILED] [%m] %s", `"__name`");                      \
    end                                                                           \
    if ((__wait) && !__name``_wait_q) __name``_data_q <= (__data);                \
    __name``_wait_q <= !(__rst) && (__wait);                                      \
  end                                                                             \
  /* verilator lint_on SYNCASYNCNET */

`define ASSERT_INIT(__name, __prop)                                             \
  initial begin : __name                                                         \
    assert (__prop) else $error("[ASSERT FAILED] [%m] %s", `"__name`");          \
  end

`else

`define ASSERT(__name, __prop, __clk, __rst)
`define ASSERT_IMPLIES(__name, __ante, __cons, __clk, __rst)
`define ASSERT_IF(__name, __cond, __prop, __clk, __rst)
`define ASSERT_NEXT(__name, __ante, __cons, __clk, __rst)
`define ASSERT_KNOWN(__name, __sig, __clk, __rst)
`define ASSERT_KNOWN_IF(__name, __cond, __sig, __clk, __rst)
`define ASSERT_STABLE(__name, __wait, __data, __clk, __rst)
`define ASSERT_INIT(__name, __prop)

`endif

`endif  // TRIRAST_ASSERT_SVH

// Cover points (functional coverage, docs/coverage.md), beside the logic they watch:
//
//   `COVER(Name, Prop, Clk, Rst)         counts the rising edges of Clk at which Prop holds
//                                        while Rst is 0 (a `cover property`)
//
// Simulation-only and switchable: they exist only under Verilator with TRIRAST_COVERAGE defined
// (the Verilated builds of cmake/trirast_rtl_builds.cmake, which also pass --coverage-user, so the
// counts land in the model's coverage database); every other tool and build sees nothing.
`ifndef TRIRAST_COVER_SVH
`define TRIRAST_COVER_SVH
`ifdef VERILATOR
`ifdef TRIRAST_COVERAGE
`define TRIRAST_COVERAGE_ON
`endif
`endif
`ifdef TRIRAST_COVERAGE_ON
`define COVER(__name, __prop, __clk, __rst)                                     \
  /* verilator lint_off SYNCASYNCNET */                                          \
  __name: cover property (@(posedge __clk) disable iff (__rst) (__prop));        \
  /* verilator lint_on SYNCASYNCNET */
`else
`define COVER(__name, __prop, __clk, __rst)
`endif
`endif  // TRIRAST_COVER_SVH

// A span port's checks (trirast_span_port, and trirast_halfspace_top's span port in block RAM):
// the handshake (a span offered and not taken stays, unchanged, next cycle), known values on the
// outputs (the valid and the count always, the span when valid), and two cover points
// (docs/coverage.md): a span waiting (valid, not ready), and ready low for two cycles or more in
// a row (the downstream's back-pressure). Clock clk_i, reset rst_ni.
`ifndef TRIRAST_SPAN_PORT_CHECKS
`define TRIRAST_SPAN_PORT_CHECKS(__valid, __ready, __data, __count)                          \
  `ASSERT_NEXT(SpanValidHeld_A, __valid && !__ready, __valid, clk_i, !rst_ni)                 \
  `ASSERT_STABLE(SpanDataStable_A, __valid && !__ready, __data, clk_i, !rst_ni)               \
  `ASSERT_KNOWN(SpanValidKnown_A, __valid, clk_i, !rst_ni)                                    \
  `ASSERT_KNOWN(FifoCountKnown_A, __count, clk_i, !rst_ni)                                    \
  `ASSERT_KNOWN_IF(SpanDataKnown_A, __valid, __data, clk_i, !rst_ni)                          \
  `COVER(SpanPortStall_C, __valid && !__ready, clk_i, !rst_ni)                                \
  `COVER(SpanReadyLow2_C, !__ready && !$past(__ready), clk_i, !rst_ni)
`endif
