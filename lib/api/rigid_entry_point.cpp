// The one entry point (exactccd/ccd.hpp's answer_query) for rigid queries (exactccd/rigid.hpp):
// the floating-point environment, validation, then the method's stage list
// (questions/rigid_methods.hpp).
#include <string>

#include "exactccd/rigid.hpp"
#include "kinds/primitive_kinds.hpp"
#include "numeric/fp_environment.hpp"
#include "questions/rigid_methods.hpp"
#include "rigid/validation.hpp"

namespace exactccd {
namespace {

template <class Query>
std::string function_name(bool want_toi) {
  return "exactccd::rigid_" + std::string(kinds::kind_of<Query>::function) + (want_toi ? "_toi" : "_ccd");
}

template <class Query>
std::optional<TimeInterval> answer(const Query& q, const CcdParams& params, Method method, bool want_toi,
                                   StageCounters* counters) {
  const numeric::DefaultFpEnvironment fp_environment;  // whatever the caller's thread has set
  rigid::validate(q, params, [&] { return function_name<Query>(want_toi); });
  const pipeline::Question question{params, want_toi};
  switch (method) {
    case Method::filtered:
      return questions::filtered_method(q, question, counters);
    case Method::exact:
      return questions::exact_method(q, question);
  }
  throw std::invalid_argument(function_name<Query>(want_toi) + ": unknown method " +
                              std::to_string(static_cast<int>(method)));
}

}  // namespace

template <>
std::optional<TimeInterval> answer_query(const RigidVertexFaceQuery& q, const CcdParams& params, Method method,
                                         bool want_toi, StageCounters* counters) {
  return answer(q, params, method, want_toi, counters);
}
template <>
std::optional<TimeInterval> answer_query(const RigidEdgeEdgeQuery& q, const CcdParams& params, Method method,
                                         bool want_toi, StageCounters* counters) {
  return answer(q, params, method, want_toi, counters);
}

}  // namespace exactccd
