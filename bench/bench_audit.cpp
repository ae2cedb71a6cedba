// pita audit at the default size: every arrow method through three
// keyframes x every property x (200 random + 7 crafted) configurations
// (issue 14 asks for at most 10 s on 2 cores).
#include <benchmark/benchmark.h>

#include "analysis/audit.hpp"

namespace {

void BM_Audit(benchmark::State& state) {
  pita::analysis::AuditOptions options;
  options.jobs = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(pita::analysis::run_audit(options).cells.size());
}
BENCHMARK(BM_Audit)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

// One property of one method on one configuration (the audit's unit of work).
void BM_Probe(benchmark::State& state) {
  const auto property = static_cast<pita::analysis::Property>(state.range(0));
  const auto configs = pita::analysis::audit_configs(1, 3);
  for (auto _ : state) {
    benchmark::DoNotOptimize(pita::analysis::probe(property, pita::Method::P6, configs.back().keyframes, 1).value);
  }
  state.SetLabel(std::string(pita::analysis::info(property).id));
}
BENCHMARK(BM_Probe)->DenseRange(0, 12)->Unit(benchmark::kMicrosecond);

}  // namespace
