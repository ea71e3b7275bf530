// Overloaded: one visitor from several lambdas, for std::visit over a command variant
// (MESSD's in dispatch.cpp, I++ DME's in ipp_commands.cpp).
#pragma once

namespace imess::net {

template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

}  // namespace imess::net
