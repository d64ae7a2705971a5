// The branch decisions of a computation, for a scalar type that knows whether its comparisons are
// certain (ball.hpp's enclosures). The mechanics name each comparison that chooses a branch by a
// DecisionName alive around it; for every other scalar the name costs nothing. While a DecisionLog is
// installed on the thread, the enclosure type records each named comparison (decided, or an exact tie)
// and every comparison it cannot decide, named or not, and takes the branch the log says.
#pragma once

#include <string>
#include <type_traits>
#include <vector>

namespace impact3d {

// The two decision names the log itself knows: what it files a comparison nobody named under, and the
// entry the strategy's constraint rows answer (constraint_rows.hpp of the mechanics); the mechanics'
// own names are in impact3d/mechanics/decisions.hpp.
namespace decision_names {
inline constexpr char unnamed[] = "a comparison the mechanics do not name";
inline constexpr char constraint_rows[] = "post-impact relative velocity: the strategy's constraint rows";
}  // namespace decision_names


// decided: the balls exclude the other branch; by_construction: the balls could not tell, and the
// strategy's own constraint rows decide it exactly (a zero that is the strategy's constraint, not a
// numerical accident); tie: exactly on the threshold, by the exact solve; undecided: open.
enum class DecisionStatus { decided, by_construction, undecided, tie };

inline const char* decision_status_name(DecisionStatus s) {
  switch (s) {
    case DecisionStatus::decided: return "decided";
    case DecisionStatus::by_construction: return "by construction";
    case DecisionStatus::undecided: return "undecided";
    case DecisionStatus::tie: return "tie";
  }
  return "?";
}

struct Decision {
  std::string name;
  DecisionStatus status = DecisionStatus::decided;
  std::string detail;  // the compared difference's enclosure, and the branch taken
};

// What one computation decided, one entry per name (a name compared several times keeps its least
// certain status and that comparison's detail), and which undecided name, if any, takes its other branch.
struct DecisionLog {
  std::vector<Decision> decisions;
  std::string flip;  // the name whose undecided comparisons take the branch the midpoint does not

  void record(const char* name, DecisionStatus status, std::string detail) {
    for (auto& d : decisions)
      if (d.name == name) {
        if (rank(status) > rank(d.status)) d = {name, status, std::move(detail)};
        return;
      }
    decisions.push_back({name, status, std::move(detail)});
  }
  // An answer of the constraint rows, added to the one entry of that name.
  void by_construction(const std::string& answer) {
    for (auto& d : decisions)
      if (d.name == decision_names::constraint_rows) {
        if (d.detail.find(answer) == std::string::npos) d.detail += "; " + answer;
        return;
      }
    decisions.push_back({decision_names::constraint_rows, DecisionStatus::by_construction, answer});
  }
  bool undecided() const {
    for (const auto& d : decisions)
      if (d.status == DecisionStatus::undecided) return true;
    return false;
  }

  static inline thread_local DecisionLog* current = nullptr;
  static inline thread_local const char* current_name = nullptr;

 private:
  static int rank(DecisionStatus s) { return s == DecisionStatus::undecided ? 2 : s == DecisionStatus::tie ? 1 : 0; }
};

// Installs a log on this thread for its lifetime.
class DecisionRecording {
 public:
  explicit DecisionRecording(DecisionLog& log) : previous_(DecisionLog::current) { DecisionLog::current = &log; }
  ~DecisionRecording() { DecisionLog::current = previous_; }
  DecisionRecording(const DecisionRecording&) = delete;
  DecisionRecording& operator=(const DecisionRecording&) = delete;

 private:
  DecisionLog* previous_;
};

// A branch imposed on a named decision, for every scalar type, while an ImposeBranch holds it on the
// thread: a reconstruction fits each regime's model on its own, then checks that the regime it imposed
// is the one the fitted inputs decide (studies/reconstruct.hpp). Names compare by address: each is one
// inline array.
struct ImposedBranch {
  const char* name = nullptr;
  bool value = false;
  static inline thread_local const ImposedBranch* current = nullptr;
};

// `decided`, unless a branch is imposed on `name`.
inline bool imposed_or(const char* name, bool decided) {
  const ImposedBranch* b = ImposedBranch::current;
  return b && b->name == name ? b->value : decided;
}

// Imposes `branch` (none: nullptr) on this thread for its lifetime.
class ImposeBranch {
 public:
  explicit ImposeBranch(const ImposedBranch* branch) : previous_(ImposedBranch::current) { ImposedBranch::current = branch; }
  ~ImposeBranch() { ImposedBranch::current = previous_; }
  ImposeBranch(const ImposeBranch&) = delete;
  ImposeBranch& operator=(const ImposeBranch&) = delete;

 private:
  const ImposedBranch* previous_;
};

// The name of the comparisons made while it lives, for the scalar types that record them.
template <typename Scalar, typename = void>
struct DecisionName {
  constexpr explicit DecisionName(const char*) {}
  // Not trivial, as the recording guard's is not: a guard held only for its lifetime is then not an
  // unused variable to clang, whatever the scalar.
  constexpr ~DecisionName() {}
};

template <typename Scalar>
struct DecisionName<Scalar, std::enable_if_t<Scalar::records_decisions>> {
  explicit DecisionName(const char* name) : previous_(DecisionLog::current_name) { DecisionLog::current_name = name; }
  ~DecisionName() { DecisionLog::current_name = previous_; }
  DecisionName(const DecisionName&) = delete;
  DecisionName& operator=(const DecisionName&) = delete;

 private:
  const char* previous_;
};

}  // namespace impact3d
