#include "orient/Covariogram.h"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>

#include "common/Error.h"
#include "common/ParallelFor.h"

namespace mixengine::orient {
namespace {

struct FftwFree {
    void operator()(void* p) const { fftw_free(p); }
};
using ComplexBuffer = std::unique_ptr<fftw_complex[], FftwFree>;

struct PlanDeleter {
    void operator()(fftw_plan_s* p) const { fftw_destroy_plan(p); }
};
using Plan = std::unique_ptr<fftw_plan_s, PlanDeleter>;

/// A padded grid and its spectrum.
struct Spectrum {
    std::array<int, 3> size{};
    std::size_t complex_count = 0;
    ComplexBuffer data;
};

std::size_t realCount(const std::array<int, 3>& n) {
    return static_cast<std::size_t>(n[0]) * n[1] * n[2];
}
std::size_t halfCount(const std::array<int, 3>& n) {
    return static_cast<std::size_t>(n[0]) * n[1] * (n[2] / 2 + 1);
}

std::array<int, 3> reachCells(const GridFrame& frame, double reach_mm) {
    std::array<int, 3> k{};
    for (int a = 0; a < 3; ++a) {
        const int by_reach = static_cast<int>(std::ceil(reach_mm / frame.step_mm[a])) + 1;
        k[a] = std::min(frame.cells[a], by_reach);
    }
    return k;
}

std::array<int, 3> paddedSize(const GridFrame& frame, const std::array<int, 3>& reach) {
    return {fastFftSize(frame.cells[0] + reach[0]), fastFftSize(frame.cells[1] + reach[1]),
            fastFftSize(frame.cells[2] + reach[2])};
}

bool sameFrame(const GridFrame& a, const GridFrame& b) {
    return a.cells == b.cells && a.step_mm == b.step_mm && a.origin_mm == b.origin_mm;
}

/// Real values in an in-place r2c buffer: rows of the last axis are 2 (n2/2 + 1) doubles long.
std::size_t rowStride(const std::array<int, 3>& n) {
    return 2 * (static_cast<std::size_t>(n[2]) / 2 + 1);
}

/// The grid, zero-padded, as the real input of an in-place transform.
ComplexBuffer paddedCopy(const VoxelGrid& grid, const std::array<int, 3>& n) {
    ComplexBuffer buffer(fftw_alloc_complex(halfCount(n)));
    double* real = reinterpret_cast<double*>(buffer.get());
    std::fill(real, real + 2 * halfCount(n), 0.0);
    const auto& c = grid.frame.cells;
    for (int i = 0; i < c[0]; ++i) {
        for (int j = 0; j < c[1]; ++j) {
            const float* src = &grid.fraction[(static_cast<std::size_t>(i) * c[1] + j) * c[2]];
            std::copy(src, src + c[2], &real[(static_cast<std::size_t>(i) * n[1] + j) * rowStride(n)]);
        }
    }
    return buffer;
}

/// Z = IFFT(X̂ · conj(Ŷ)) restricted to shifts within the reach, scaled to mm³.
std::vector<float> inverseWithin(fftw_plan_s* plan, const double* out, const std::array<int, 3>& n,
                                 const std::array<int, 3>& k, double scale) {
    fftw_execute(plan);
    const int w0 = 2 * k[0] + 1, w1 = 2 * k[1] + 1, w2 = 2 * k[2] + 1;
    std::vector<float> values(static_cast<std::size_t>(w0) * w1 * w2);
    for (int a = -k[0]; a <= k[0]; ++a) {
        for (int b = -k[1]; b <= k[1]; ++b) {
            for (int c = -k[2]; c <= k[2]; ++c) {
                const std::size_t src =
                    (static_cast<std::size_t>((a + n[0]) % n[0]) * n[1] + (b + n[1]) % n[1]) * rowStride(n) +
                    (c + n[2]) % n[2];
                const std::size_t dst =
                    (static_cast<std::size_t>(a + k[0]) * w1 + (b + k[1])) * w2 + (c + k[2]);
                values[dst] = static_cast<float>(std::max(0.0, out[src] * scale));
            }
        }
    }
    return values;
}

}  // namespace

int fastFftSize(int n) {
    for (int m = std::max(1, n);; ++m) {
        int r = m;
        for (const int p : {2, 3, 5, 7}) {
            while (r % p == 0)
                r /= p;
        }
        if (r == 1)
            return m;
    }
}

double CorrelationField::atCell(int a, int b, int c) const {
    if (std::abs(a) > reach_[0] || std::abs(b) > reach_[1] || std::abs(c) > reach_[2])
        return 0.0;
    const int w1 = 2 * reach_[1] + 1, w2 = 2 * reach_[2] + 1;
    return values_[(static_cast<std::size_t>(a + reach_[0]) * w1 + (b + reach_[1])) * w2 + (c + reach_[2])];
}

double CorrelationField::at(const Vec3& v_mm) const {
    const double t[3] = {v_mm.x / step_mm_[0], v_mm.y / step_mm_[1], v_mm.z / step_mm_[2]};
    int i0[3];
    double f[3];
    for (int a = 0; a < 3; ++a) {
        const double fl = std::floor(t[a]);
        i0[a] = static_cast<int>(fl);
        f[a] = t[a] - fl;
    }
    double sum = 0;
    for (int corner = 0; corner < 8; ++corner) {
        double w = 1;
        int idx[3];
        for (int a = 0; a < 3; ++a) {
            const int bit = (corner >> a) & 1;
            idx[a] = i0[a] + bit;
            w *= bit ? f[a] : 1 - f[a];
        }
        if (w > 0)
            sum += w * atCell(idx[0], idx[1], idx[2]);
    }
    return sum;
}

std::vector<CorrelationField> correlate(const std::vector<const VoxelGrid*>& grids,
                                        const std::vector<CorrelationPair>& pairs, double reach_mm,
                                        int threads) {
    std::vector<Spectrum> spectra(grids.size());
    std::vector<Plan> forward(grids.size());
    for (std::size_t g = 0; g < grids.size(); ++g) {  // FFTW's planner is not thread-safe
        const auto n = paddedSize(grids[g]->frame, reachCells(grids[g]->frame, reach_mm));
        spectra[g].size = n;
        spectra[g].complex_count = halfCount(n);
        spectra[g].data = paddedCopy(*grids[g], n);  // transformed in place
        fftw_complex* data = spectra[g].data.get();
        forward[g].reset(
            fftw_plan_dft_r2c_3d(n[0], n[1], n[2], reinterpret_cast<double*>(data), data, FFTW_ESTIMATE));
    }
    parallelFor(grids.size(), threads, [&](std::size_t g) { fftw_execute(forward[g].get()); });

    std::vector<ComplexBuffer> products(pairs.size());  // inverse-transformed in place
    std::vector<Plan> inverse(pairs.size());
    for (std::size_t p = 0; p < pairs.size(); ++p) {
        const VoxelGrid& x = *grids[pairs[p].x];
        if (!sameFrame(x.frame, grids[pairs[p].y]->frame))
            throw InternalError("orient: correlated grids must share one frame");
        const auto& n = spectra[pairs[p].x].size;
        products[p].reset(fftw_alloc_complex(halfCount(n)));
        fftw_complex* data = products[p].get();
        inverse[p].reset(
            fftw_plan_dft_c2r_3d(n[0], n[1], n[2], data, reinterpret_cast<double*>(data), FFTW_ESTIMATE));
    }
    std::vector<CorrelationField> fields(pairs.size());
    parallelFor(pairs.size(), threads, [&](std::size_t p) {
        const Spectrum& sx = spectra[pairs[p].x];
        const Spectrum& sy = spectra[pairs[p].y];
        for (std::size_t i = 0; i < sx.complex_count; ++i) {
            const std::complex<double> a(sx.data[i][0], sx.data[i][1]), b(sy.data[i][0], sy.data[i][1]);
            const std::complex<double> z = a * std::conj(b);
            products[p][i][0] = z.real();
            products[p][i][1] = z.imag();
        }
        const GridFrame& frame = grids[pairs[p].x]->frame;
        const auto k = reachCells(frame, reach_mm);
        const double scale = frame.cellVolumeMm3() / static_cast<double>(realCount(sx.size));
        fields[p] = CorrelationField(
            frame.step_mm, k,
            inverseWithin(inverse[p].get(), reinterpret_cast<const double*>(products[p].get()), sx.size, k,
                          scale));
    });
    return fields;
}

}  // namespace mixengine::orient
