// fpmshell_crash_kernels: the element kernel of the plastic sections of a crash run, timed on
// one thread in ns per element-step (docs/performance.md, "Crash kernels"). Every point of
// every element yields at every timed step: the cost of the return mapping at its worst.
//
// The model is the steady plastic plate of bench_models.hpp (a homogeneous biaxial stretch and
// bending prescribed on the edges and given as the initial velocity; 5 Lobatto points through
// the thickness x 3 in-plane points) with the section's material one of:
//   jc        Johnson-Cook A = 180 MPa, B = 450 MPa, n = 0.5 (the crushed half-cylinder)
//   jc-rate   the same with C = 0.02, reference rate 1 /s (the rate factor at every point)
//   jc-n0.1   Johnson-Cook n = 0.1 (a flow curve steep at small plastic strain)
//   bilinear  J2, sigma_y = 250 MPa, E_t = E / 21 (the plate of `fpmshell_bench --table`)
//   elastic   the same section linear elastic: the cost of everything but the return mapping
//   tab       tabulated: the jc curve sampled at 21 points to a plastic strain of 0.5 (how a
//             user's LS-DYNA *MAT_024 curve looks; not in the default list, which an older
//             build must run too)
//   tab-rate  three such curves at 0.001, 1 and 1000 /s, 1, 1.1 and 1.2 times the jc curve
//   jc-damage jc with Johnson-Cook damage (failure/johnson_cook) whose failure strain no point
//             reaches: the cost of the damage's accumulation at every point of every step (not
//             in the default list, which an older build must run too)
//   jc-fail   jc with failure at a plastic strain of 10 (failure/plastic_strain): the cost of
//             the erosion's bookkeeping (idem)
// The stretch rate is set from the stable step so that the points reach the yield surface
// after 10 steps; the samples start after 14. A sample times ShellElements::compute on a twin
// of the solver's elements, given the solver's current path element (an untimed copy),
// `batch` times in a row: its points keep yielding under the same increment. Time: the
// thread's CPU time (the machine may be shared), in ns per element-step.
//
// The source uses only the library's model and solver interface, so that the same file builds
// against another build of the library (tools/interleaved_kernels.py compares two builds).
//
// usage: fpmshell_crash_kernels [--models jc,jc-rate,jc-n0.1,bilinear,elastic,tab,tab-rate] [--n
// 71] [--samples 7]
//                               [--batch 10]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <sstream>
#include <string>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "../bench_models.hpp"
#include "fpmshell/failure/johnson_cook/johnson_cook_damage.hpp"
#include "fpmshell/failure/plastic_strain/plastic_strain_failure.hpp"
#include "fpmshell/materials/bilinear/bilinear_law.hpp"
#include "fpmshell/materials/johnson_cook/johnson_cook_law.hpp"
#include "fpmshell/materials/tabulated/tabulated_law.hpp"
#include "fpmshell/mesh/generators.hpp"
#include "fpmshell/model/mesh_topology.hpp"
#include "fpmshell/solver/explicit_solver.hpp"
#include "fpmshell/solver/shell_elements.hpp"

namespace {

using namespace fpmshell;

constexpr int k_steps_to_yield = 10;

/// The plastic plate of n x n squares (2 n^2 triangles), steel 2 mm, 5 x 3 points, `material`
/// (its elastic constants are overwritten), yielding at step k_steps_to_yield.
Model steady_plate(Index n, Material material, Real yield_stress) {
    PlateParams pp;
    pp.nx = pp.ny = n;
    pp.pattern = DiagonalPattern::Alternate;
    MeshData mesh = generate_plate(pp);
    Model m;
    m.title = "crash kernel plate";
    m.nodes = mesh.nodes;
    m.triangles = mesh.triangles;
    material.name = "steel";
    material.density = 7800;
    material.youngs_modulus = 2.1e11;
    material.poisson_ratio = 0.3;
    m.materials.push_back(material);
    m.sections.push_back({0, 0.002, 5, 3});
    m.element_section.assign(m.triangles.size(), 0);
    m.control.end_time = 1;
    // The stable step of the regular mesh: the membrane step of its triangles (legs 1 / n) or
    // the solver's own, whichever the solver reports after its set-up.
    const Real dt = ExplicitSolver(m).stable_dt();
    bench::impose_steady_flow(m, mesh.node_sets.at("boundary"), yield_stress, k_steps_to_yield, dt);
    return m;
}

struct Case {
    std::string name;
    Material material;
    Real yield_stress;
};

Case make_case(const std::string& name) {
    Material m;
    m.youngs_modulus = 2.1e11;  // steady_plate's (the bilinear curve's plastic modulus reads it)
    if (name == "elastic") {    // the same section elastic: the floor of the plastic rows
        return {name, m, 250e6};
    }
    if (name == "bilinear") {
        make_bilinear(m, 250e6, 1e10);
        return {name, m, 250e6};
    }
    if (name == "tab" || name == "tab-rate") {
        std::vector<FlowCurvePoints> curves;
        for (Real scale :
             name == "tab" ? std::vector<Real>{1.0} : std::vector<Real>{1.0, 1.1, 1.2}) {
            FlowCurvePoints c;
            c.strain_rate = scale == 1.0 ? 1e-3 : scale == 1.1 ? 1.0 : 1e3;
            for (int i = 0; i <= 20; ++i) {
                const Real alpha = 0.5 * (i / 20.0) * (i / 20.0);  // denser at small strains
                c.strain.push_back(alpha);
                c.stress.push_back(scale * (180e6 + 450e6 * std::sqrt(alpha)));
            }
            curves.push_back(c);
        }
        make_tabulated(m, curves);
        return {name, m, 180e6};
    }
    make_johnson_cook(m, 180e6, 450e6, name == "jc-n0.1" ? 0.1 : 0.5,
                      name == "jc-rate" ? 0.02 : 0.0, 1.0);
    if (name == "jc-damage") {  // D1 = 10: eps_f >= 10, never reached
        m.failure.criteria.push_back(
            {"johnson_cook", JohnsonCookDamageParameters{10.0, 0.5, -1.5, 0.01, 0.0, 1.0, 1e-6}});
    } else if (name == "jc-fail") {  // never reached: the erosion's bookkeeping alone
        add_plastic_strain_failure(m, 10.0);
    } else if (name != "jc-rate" && name != "jc" && name != "jc-n0.1") {
        std::fprintf(
            stderr,
            "unknown model %s (jc, jc-rate, jc-n0.1, jc-damage, jc-fail, bilinear, elastic, tab, "
            "tab-rate)\n",
            name.c_str());
        std::exit(2);
    }
    return {name, m, 180e6};
}

/// CPU time of the calling thread: on a machine shared with other work, the time the kernel
/// ran, not the time it waited for a core.
double thread_cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// The plastic strain of every (element, thickness point) pair, averaged in the plane.
std::vector<Real> plastic_strains(const ShellElements& el) {
    std::vector<Real> out;
    for (Index e = 0; e < el.size(); ++e)
        for (int k = 0; k < el.thickness_points(e); ++k) out.push_back(el.plastic_strain(e, k));
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    std::string models = "jc,jc-rate,jc-n0.1,bilinear,elastic";
    Index n = 71;
    int samples = 7, batch = 10;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (i + 1 >= argc) {
            std::fprintf(stderr, "%s needs a value\n", a.c_str());
            return 2;
        }
        const std::string v = argv[++i];
        if (a == "--models")
            models = v;
        else if (a == "--n")
            n = std::atoi(v.c_str());
        else if (a == "--samples")
            samples = std::max(1, std::atoi(v.c_str()));
        else if (a == "--batch")
            batch = std::max(1, std::atoi(v.c_str()));
        else {
            std::fprintf(stderr, "unknown option %s\n", a.c_str());
            return 2;
        }
    }
#ifdef _OPENMP
    omp_set_num_threads(1);
#endif
    std::printf("| model | elements | ns / element-step (median of %d) | min | yielding |\n",
                samples);
    std::printf("|---|---:|---:|---:|---:|\n");
    std::stringstream list(models);
    std::string name;
    while (std::getline(list, name, ',')) {
        const Case c = make_case(name);
        const Model m = steady_plate(n, c.material, c.yield_stress);
        ExplicitSolver solver(m);
        const MeshTopology topology(m);
        ShellElements twin(m, topology);
        ParticleState ps = solver.state();
        auto sync = [&] {
            const ParticleState& s = solver.state();
            ps.x_prev = s.x_prev;
            ps.x = s.x;
            ps.dtheta = s.dtheta;
            ps.drill_axis = s.drill_axis;
        };
        auto compute = [&] { (void)twin.compute(ps, 0.0, solver.last_dt()); };
        for (int i = 0; i < k_steps_to_yield + 4; ++i) {  // the twin in step with the solver
            sync();
            compute();
            solver.step(1e30);
        }
        std::vector<double> ns;
        const double es = static_cast<double>(batch) * static_cast<double>(m.n_elements());
        double share = 1;
        for (int s = 0; s < samples; ++s) {
            solver.step(1e30);
            sync();
            if (s == 0) {  // one untimed compute: the share of the pairs whose strain grows
                const std::vector<Real> before = plastic_strains(twin);
                compute();
                const std::vector<Real> after = plastic_strains(twin);
                long grew = 0;
                for (std::size_t i = 0; i < before.size(); ++i) grew += after[i] > before[i];
                share = static_cast<double>(grew) / static_cast<double>(before.size());
            }
            const double t0 = thread_cpu_seconds();
            for (int b = 0; b < batch; ++b) compute();
            ns.push_back((thread_cpu_seconds() - t0) * 1e9 / es);
        }
        std::printf("| %s | %d | %.0f | %.0f | %.1f %% |\n", c.name.c_str(), m.n_elements(),
                    median(ns), *std::min_element(ns.begin(), ns.end()), 100 * share);
        std::fflush(stdout);
    }
    return 0;
}
