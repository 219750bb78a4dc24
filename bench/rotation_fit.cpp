// The ARAP local step's rotation per element (geometry/maps/rotation_fit.h) against the SVD it
// replaced (closest_rotation() of frontends/simplex_assembly/disassembly.h, Eigen's 3 x 3
// JacobiSVD), on matrices shaped like the local step's A_i C_i: rotations times a distortion of
// singular values in [0.7, 1.4], a tenth of them reflected (inverted simplices).
//   Svd       the old local step
//   Cold      fit_rotation(M): no hint (an ARAP run's first iteration)
//   Warm/k    fit_rotation(M, hint) with the hint the answer for M turned by 10^-k radians about a
//             random axis (the last iteration's rotation: late iterations move it by 1e-6 and
//             less, early ones by 1e-2)
//
//   bench_rotation_fit [--benchmark_filter=...] [--benchmark_repetitions=3]
#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <random>
#include <vector>

#include "frontends/simplex_assembly/disassembly.h"
#include "geometry/maps/rotation_fit.h"

namespace {

using sa::Mat;

constexpr int kMatrices = 4096;

struct Inputs {
    std::vector<Mat<3>> matrices, answers;
};

const Inputs& inputs() {
    static const Inputs in = [] {
        Inputs in;
        std::mt19937_64 rng(7);
        std::normal_distribution<double> normal;
        std::uniform_real_distribution<double> scale(0.7, 1.4);
        auto rotation = [&] {
            const Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
            return Mat<3>(q.normalized().toRotationMatrix());
        };
        for (int i = 0; i < kMatrices; ++i) {
            Eigen::Vector3d s(scale(rng), scale(rng), scale(rng));
            if (i % 10 == 0) s[2] = -s[2];
            in.matrices.push_back(rotation() * s.asDiagonal() * rotation());
            in.answers.push_back(sa::closest_rotation<3>(in.matrices.back()));
        }
        return in;
    }();
    return in;
}

void Svd(benchmark::State& state) {
    const Inputs& in = inputs();
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(sa::closest_rotation<3>(in.matrices[i]));
        i = (i + 1) % kMatrices;
    }
}
BENCHMARK(Svd);

void Cold(benchmark::State& state) {
    const Inputs& in = inputs();
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(sa::fit_rotation<3>(in.matrices[i]));
        i = (i + 1) % kMatrices;
    }
}
BENCHMARK(Cold);

void Warm(benchmark::State& state) {
    const Inputs& in = inputs();
    std::mt19937_64 rng(11);
    std::normal_distribution<double> normal;
    const double angle = std::pow(10.0, -double(state.range(0)));
    std::vector<Mat<3>> hints;
    for (const Mat<3>& answer : in.answers) {
        const Eigen::Vector3d axis = Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
        hints.push_back(answer * Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix());
    }
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(sa::fit_rotation<3>(in.matrices[i], hints[i]));
        i = (i + 1) % kMatrices;
    }
}
BENCHMARK(Warm)->Arg(2)->Arg(4)->Arg(6)->Arg(9);

}  // namespace

BENCHMARK_MAIN();
