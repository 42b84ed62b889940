// The list of the command line's motion models (motion.hpp) and the `--motion` option derived
// from it: a third model is one more traits type in Motions.
#pragma once

#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "linear_motion.hpp"
#include "rigid_motion.hpp"

namespace exactccd::cli {

/// Every motion model, in --motion's order; the first is the default.
using Motions = std::tuple<LinearMotion, RigidMotion>;

/// The names of Motions, in order.
inline std::vector<std::string> motion_names() {
  return std::apply([](auto... m) { return std::vector<std::string>{decltype(m)::name...}; }, Motions{});
}

/// The `--motion` option (the names of Motions; the first by default), with a subcommand's help.
inline OptionSpec motion_option(const std::string& help) {
  const std::vector<std::string> names = motion_names();
  return choice_option("--motion", "MODEL", names, names.front(), help);
}

/// f(M{}) for the motion model M that --motion names; every model's call returns the same type.
template <class F>
auto visit_motion(const ParsedOptions& options, F&& f) {
  const std::string& given = options.text("--motion");
  using R = decltype(f(std::tuple_element_t<0, Motions>{}));
  return std::apply(
      [&](auto... m) {
        R result{};
        const bool found = ((given == decltype(m)::name ? (result = f(m), true) : false) || ...);
        if (!found) throw std::logic_error("--motion " + given + ": no such motion model");
        return result;
      },
      Motions{});
}

/// The name of subcommand `sub` as its errors print it: "bench", or "bench --motion rigid" for
/// a model other than the default.
template <class Motion>
std::string subcommand_name(const std::string& sub) {
  return std::is_same_v<Motion, std::tuple_element_t<0, Motions>> ? sub : sub + " --motion " + Motion::name;
}

}  // namespace exactccd::cli
