// The one entry point of the library's queries (exactccd/ccd.hpp, exactccd/rational.hpp,
// exactccd/rigid.hpp): the floating-point environment, validation, then the method's stage
// lists (questions/methods.hpp, questions/rigid_methods.hpp). Every public query function is a
// one-line call of answer_query or answer_rational_query, which this file defines for every
// kind of both motion models, linear and rigid: one function, whose query check is the motion
// model's (require_valid_query) and whose parameter check is the same for both.
#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "api/checked_query.hpp"
#include "api/number_text.hpp"
#include "exact/exact_ccd.hpp"
#include "exactccd/ccd.hpp"
#include "exactccd/rational.hpp"
#include "exactccd/rigid.hpp"
#include "kinds/primitive_kinds.hpp"
#include "numeric/fp_environment.hpp"
#include "questions/methods.hpp"
#include "questions/rigid_methods.hpp"
#include "rigid/validation.hpp"
#include "separation/exact_separation.hpp"

namespace exactccd {
namespace {

/// True for the query types of the rigid motion model (exactccd/rigid.hpp).
template <class Query>
inline constexpr bool is_rigid = std::is_same_v<Query, RigidVertexFaceQuery> || std::is_same_v<Query, RigidEdgeEdgeQuery>;

/// The public function a query of this type was asked through, for error messages.
template <class Query>
std::string function_name(bool want_toi) {
  const std::string motion = is_rigid<Query> ? "rigid_" : "";
  return "exactccd::" + motion + std::string(kinds::kind_of<Query>::function) + (want_toi ? "_toi" : "_ccd");
}

/// Throws std::invalid_argument naming the function on a non-finite coordinate of a linear
/// query.
template <class Query>
void require_valid_query(const Query& q, bool want_toi) {
  using Kind = kinds::kind_of<Query>;
  for (const auto& v : rows(q)) {
    bool finite = std::isfinite(v.x) && std::isfinite(v.y);
    if constexpr (Kind::dimension == 3) finite = finite && std::isfinite(v.z);
    if (!finite)
      throw std::invalid_argument(function_name<Query>(want_toi) + ": non-finite coordinate (NaN or infinity) in the query");
  }
}

/// Throws std::invalid_argument naming the function on a rigid query that is bad input (a
/// non-finite number, a quaternion path through 0: rigid/validation.hpp).
template <class Query>
void require_valid_rigid_query(const Query& q, bool want_toi) {
  if (const std::optional<std::string> why = rigid::invalid_query(q))
    throw std::invalid_argument(function_name<Query>(want_toi) + ": " + *why);
}
/// See require_valid_rigid_query.
void require_valid_query(const RigidVertexFaceQuery& q, bool want_toi) { require_valid_rigid_query(q, want_toi); }
/// See require_valid_rigid_query.
void require_valid_query(const RigidEdgeEdgeQuery& q, bool want_toi) { require_valid_rigid_query(q, want_toi); }

/// Throws std::invalid_argument naming the function on a d that is negative or not finite, a
/// tmax outside (0, 1] or an unknown method value (numbers as they read back: number_text.hpp).
template <class Query>
void require_valid(const CcdParams& p, Method method, bool want_toi) {
  if (!(std::isfinite(p.min_distance) && p.min_distance >= 0))
    throw std::invalid_argument(function_name<Query>(want_toi) + ": min_distance must be finite and >= 0, not " +
                                shortest_text(p.min_distance));
  if (!(p.tmax > 0 && p.tmax <= 1))
    throw std::invalid_argument(function_name<Query>(want_toi) + ": tmax must be in (0, 1], not " + shortest_text(p.tmax));
  if (method != Method::filtered && method != Method::exact)
    throw std::invalid_argument(function_name<Query>(want_toi) + ": unknown method " +
                                std::to_string(static_cast<int>(method)));
}

/// answer_query for both motion models: the environment, the query's and the parameters'
/// checks, the method's stage list.
template <class Query>
std::optional<TimeInterval> answer(const Query& q, const CcdParams& params, Method method, bool want_toi,
                                   StageCounters* counters) {
  const numeric::DefaultFpEnvironment fp_environment;  // whatever the caller's thread has set
  require_valid_query(q, want_toi);
  require_valid<Query>(params, method, want_toi);
  const pipeline::Question question{params, want_toi};
  if (method == Method::exact) return questions::exact_method(q, question);
  return questions::filtered_method(q, question, counters);
}

/// require_valid_query for query `index` of a batch: the same message, with the index.
template <class Query>
void require_valid_batch_query(const Query& q, std::size_t index, bool want_toi) {
  try {
    require_valid_query(q, want_toi);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string(e.what()) + " (query " + std::to_string(index) + " of the batch)");
  }
}

}  // namespace

template <class Query>
void answer_batch(const Query* queries, std::size_t count, const CcdParams& params, Method method, bool want_toi,
                  std::optional<TimeInterval>* answers, StageCounters* counters) {
  const numeric::DefaultFpEnvironment fp_environment;  // whatever the caller's thread has set
  require_valid<Query>(params, method, want_toi);
  for (std::size_t i = 0; i < count; ++i) require_valid_batch_query(queries[i], i, want_toi);
  const pipeline::Question question{params, want_toi};
  if constexpr (!is_rigid<Query>) {  // rigid queries: no block stages yet, one by one
    if (method == Method::filtered) return questions::filtered_batch(queries, count, question, counters, answers);
  }
  for (std::size_t i = 0; i < count; ++i)
    answers[i] = method == Method::exact ? questions::exact_method(queries[i], question)
                                         : questions::filtered_method(queries[i], question, counters);
}

template <class Query>
std::optional<TimeInterval> answer_query(const Query& q, const CcdParams& params, Method method, bool want_toi,
                                         StageCounters* counters) {
  return answer(q, params, method, want_toi, counters);
}

// The rigid query types' answer_query (explicit specializations declared by exactccd/rigid.hpp).
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

template <class Query>
std::optional<TimeInterval> answer_checked_query(const Query& q, const CcdParams& params, bool want_toi) {
  return questions::filtered_method(q, pipeline::Question{params, want_toi}, nullptr);
}

template <class RationalQuery>
std::optional<TimeInterval> answer_rational_query(const RationalQuery& q, const RationalCcdParams& p, bool want_toi) {
  const numeric::DefaultFpEnvironment fp_environment;  // CGAL's kernel filters with intervals
  if (!(p.min_distance >= 0))
    throw std::invalid_argument(function_name<RationalQuery>(want_toi) + ": min_distance must be >= 0");
  if (!(p.tmax > 0 && p.tmax <= 1))
    throw std::invalid_argument(function_name<RationalQuery>(want_toi) + ": tmax must be in (0, 1]");
  constexpr bool contact_kind = std::is_same_v<RationalQuery, RationalVertexFaceQuery> ||
                                std::is_same_v<RationalQuery, RationalEdgeEdgeQuery>;
  if constexpr (contact_kind) {  // the contact question: the contact rule's exact path
    if (p.contact_over_whole_step())
      return want_toi ? exact::toi(q) : (exact::ccd(q) ? std::optional(TimeInterval{}) : std::nullopt);
  }
  return separation::exact_toi(q, p);
}

// The entry points of every kind (tests/api/test_interfaces calls each of both through
// kinds::for_each_kind, so that a kind missing here fails to link).
template std::optional<TimeInterval> answer_query(const VertexFaceQuery&, const CcdParams&, Method, bool, StageCounters*);
template std::optional<TimeInterval> answer_query(const EdgeEdgeQuery&, const CcdParams&, Method, bool, StageCounters*);
template std::optional<TimeInterval> answer_query(const PointEdgeQuery&, const CcdParams&, Method, bool, StageCounters*);
template std::optional<TimeInterval> answer_query(const PointPointQuery&, const CcdParams&, Method, bool, StageCounters*);
template std::optional<TimeInterval> answer_query(const EdgeEdge2dQuery&, const CcdParams&, Method, bool, StageCounters*);
template std::optional<TimeInterval> answer_query(const PointEdge2dQuery&, const CcdParams&, Method, bool, StageCounters*);
template std::optional<TimeInterval> answer_query(const PointPoint2dQuery&, const CcdParams&, Method, bool, StageCounters*);

template void answer_batch(const VertexFaceQuery*, std::size_t, const CcdParams&, Method, bool,
                           std::optional<TimeInterval>*, StageCounters*);
template void answer_batch(const EdgeEdgeQuery*, std::size_t, const CcdParams&, Method, bool,
                           std::optional<TimeInterval>*, StageCounters*);
template void answer_batch(const PointEdgeQuery*, std::size_t, const CcdParams&, Method, bool,
                           std::optional<TimeInterval>*, StageCounters*);
template void answer_batch(const PointPointQuery*, std::size_t, const CcdParams&, Method, bool,
                           std::optional<TimeInterval>*, StageCounters*);
template void answer_batch(const EdgeEdge2dQuery*, std::size_t, const CcdParams&, Method, bool,
                           std::optional<TimeInterval>*, StageCounters*);
template void answer_batch(const PointEdge2dQuery*, std::size_t, const CcdParams&, Method, bool,
                           std::optional<TimeInterval>*, StageCounters*);
template void answer_batch(const PointPoint2dQuery*, std::size_t, const CcdParams&, Method, bool,
                           std::optional<TimeInterval>*, StageCounters*);
template void answer_batch(const RigidVertexFaceQuery*, std::size_t, const CcdParams&, Method, bool,
                           std::optional<TimeInterval>*, StageCounters*);
template void answer_batch(const RigidEdgeEdgeQuery*, std::size_t, const CcdParams&, Method, bool,
                           std::optional<TimeInterval>*, StageCounters*);

template std::optional<TimeInterval> answer_checked_query(const VertexFaceQuery&, const CcdParams&, bool);
template std::optional<TimeInterval> answer_checked_query(const EdgeEdgeQuery&, const CcdParams&, bool);
template std::optional<TimeInterval> answer_checked_query(const PointEdgeQuery&, const CcdParams&, bool);
template std::optional<TimeInterval> answer_checked_query(const PointPointQuery&, const CcdParams&, bool);
template std::optional<TimeInterval> answer_checked_query(const EdgeEdge2dQuery&, const CcdParams&, bool);
template std::optional<TimeInterval> answer_checked_query(const PointEdge2dQuery&, const CcdParams&, bool);
template std::optional<TimeInterval> answer_checked_query(const PointPoint2dQuery&, const CcdParams&, bool);

template std::optional<TimeInterval> answer_rational_query(const RationalVertexFaceQuery&, const RationalCcdParams&, bool);
template std::optional<TimeInterval> answer_rational_query(const RationalEdgeEdgeQuery&, const RationalCcdParams&, bool);
template std::optional<TimeInterval> answer_rational_query(const RationalPointEdgeQuery&, const RationalCcdParams&, bool);
template std::optional<TimeInterval> answer_rational_query(const RationalPointPointQuery&, const RationalCcdParams&, bool);
template std::optional<TimeInterval> answer_rational_query(const RationalEdgeEdge2dQuery&, const RationalCcdParams&, bool);
template std::optional<TimeInterval> answer_rational_query(const RationalPointEdge2dQuery&, const RationalCcdParams&, bool);
template std::optional<TimeInterval> answer_rational_query(const RationalPointPoint2dQuery&, const RationalCcdParams&, bool);

}  // namespace exactccd
