#include "frontends/simplex_assembly/stage_trace.h"

#include "optim/enum_names.h"

namespace sa {

namespace {

constexpr EnumName<Stage> kStageNames[] = {{Stage::kStartUntangle, "start untangling"},
                                           {Stage::kAssembly, "assembly"},
                                           {Stage::kVertexStage, "vertex stage"},
                                           {Stage::kFallback, "fallback"}};

constexpr EnumName<UntangleOutcome> kUntangleNames[] = {
    {UntangleOutcome::kNothingFree, "no simplex has a free vertex"},
    {UntangleOutcome::kStartUntangled, "the start is untangled"},
    {UntangleOutcome::kUntangled, "untangled"},
    {UntangleOutcome::kUntangledConverged, "untangled, converged"},
    {UntangleOutcome::kNotUntangled, "not untangled"}};

constexpr EnumName<VertexStageOutcome> kVertexStageNames[] = {
    {VertexStageOutcome::kRan, "ran"},
    {VertexStageOutcome::kRanStartKept, "ran; the start is kept (no lower energy at s)"},
    {VertexStageOutcome::kRanUndone,
     "ran; undone: its result had degenerate simplices, its start none"},
    {VertexStageOutcome::kRanFromInitialMap,
     "ran from the initial map (the recovered mesh was not valid)"},
    {VertexStageOutcome::kInitialMapKept,
     "the initial map, inversion-free but beyond what the barrier represents, is kept"},
    {VertexStageOutcome::kSkippedTimeLimit, "skipped: the time limit was reached"},
    {VertexStageOutcome::kSkippedNothingMoved,
     "skipped: the initial map was valid and nothing moved"},
    {VertexStageOutcome::kSkippedInfeasibleStart,
     "skipped: the start has an inverted simplex, one over the bound or a plugin barrier at "
     "+inf"},
    {VertexStageOutcome::kSkippedPluginCannotProject, "skipped: a plugin cannot project the start"},
    {VertexStageOutcome::kSkippedBeyondExponentCap,
     "skipped: simplices so distorted that the barrier cannot rank the others"},
    {VertexStageOutcome::kSkippedWrappedStart,
     "skipped: the start wraps around an interior edge or vertex (not locally injective)"}};

constexpr EnumName<FallbackOutcome> kFallbackNames[] = {
    {FallbackOutcome::kReplaced, "replaced the result"},
    {FallbackOutcome::kNoBetter, "no better than the result, which is kept"}};

}  // namespace

bool newton_ran(VertexStageOutcome outcome) {
    return outcome == VertexStageOutcome::kRan || outcome == VertexStageOutcome::kRanStartKept ||
           outcome == VertexStageOutcome::kRanUndone ||
           outcome == VertexStageOutcome::kRanFromInitialMap;
}

StageRecord& StageTrace::add(Stage stage, StageOutcome outcome) {
    records.push_back(StageRecord{.stage = stage, .outcome = outcome});
    return records.back();
}

const StageRecord* StageTrace::last(Stage stage) const {
    for (auto r = records.rbegin(); r != records.rend(); ++r)
        if (r->stage == stage) return &*r;
    return nullptr;
}

bool StageTrace::vertex_stage_ran() const {
    for (const StageRecord& r : records) {
        const auto* o = std::get_if<VertexStageOutcome>(&r.outcome);
        if (r.stage == Stage::kVertexStage && o != nullptr && newton_ran(*o)) return true;
    }
    return false;
}

std::string to_string(Stage stage) {
    return enum_name(kStageNames, stage);
}
std::string to_string(UntangleOutcome outcome) {
    return enum_name(kUntangleNames, outcome);
}
std::string to_string(VertexStageOutcome outcome) {
    return enum_name(kVertexStageNames, outcome);
}
std::string to_string(FallbackOutcome outcome) {
    return enum_name(kFallbackNames, outcome);
}
std::string to_string(const StageOutcome& outcome) {
    return std::visit([](auto o) { return to_string(o); }, outcome);
}

}  // namespace sa
