// mesh_grading.cpp - nodes graded by the static profile (mesh_grading.h).
#include "mesh_grading.h"

#include <algorithm>
#include <cmath>

namespace uc {
namespace {

constexpr int kSamples = 4096;  // per section, to integrate and invert the monitor M(s)

// Elements per piece: at least one each, the rest by the largest shortfall against the share
// of the monitor.
std::vector<int> element_counts(const std::vector<double>& weights, int total) {
    const int pieces = static_cast<int>(weights.size());
    std::vector<int> count(pieces, 1);
    double sum = 0.0;
    for (double w : weights) sum += w;
    for (int left = total - pieces; left > 0; --left) {
        int best = 0;
        double shortfall = -INFINITY;
        for (int i = 0; i < pieces; ++i) {
            const double s = total * weights[i] / sum - count[i];
            if (s > shortfall) {
                shortfall = s;
                best = i;
            }
        }
        ++count[best];
    }
    return count;
}

}  // namespace

std::vector<double> graded_nodes(const CableModel& model, const LineProfile& profile, bool towOnTop) {
    const double L = model.line().length;
    auto turning = [&](double s) {  // from the tow point, whichever end the profile starts at
        return towOnTop ? profile.turning(s) : profile.turning(L) - profile.turning(L - s);
    };
    std::vector<double> contacts = profile.contacts();  // where the line reaches or leaves the seabed
    for (double& c : contacts) c = towOnTop ? c : L - c;
    std::vector<double> nodes{0.0};
    for (int k = 0; k < model.n_sections(); ++k) {
        const SectionProps& sec = model.section(k);
        const double s0 = sec.s0, s1 = sec.s0 + sec.length;
        const double minimum = 1e-3 * sec.length / sec.nElements;  // closer cuts merge
        std::vector<double> cuts{s0};
        auto cut = [&](double s) {
            if (s > s0 + minimum && s < s1 - minimum) cuts.push_back(s);
        };
        for (const NodeAttachment& at : model.attachments()) cut(at.s);
        for (double c : contacts) cut(c);
        cuts.push_back(s1);
        std::sort(cuts.begin(), cuts.end());
        cuts.erase(std::unique(cuts.begin(), cuts.end(), [&](double a, double b) { return b - a <= minimum; }),
                   cuts.end());
        cuts.back() = s1;
        // the monitor on a fine grid with every cut on it
        std::vector<double> s, theta;
        for (size_t j = 0; j + 1 < cuts.size(); ++j) {
            const int n = std::max(8, static_cast<int>(kSamples * (cuts[j + 1] - cuts[j]) / sec.length));
            for (int i = 0; i < n; ++i) s.push_back(cuts[j] + (cuts[j + 1] - cuts[j]) * i / n);
        }
        s.push_back(s1);
        double turned = 0.0, previous = turning(s0);
        for (double si : s) {
            const double t = turning(si);
            turned += std::abs(t - previous);
            previous = t;
            theta.push_back(turned);
        }
        const double angleScale = std::max(turned, kGradingAngle);
        std::vector<double> M(s.size());
        for (size_t i = 0; i < s.size(); ++i) M[i] = (s[i] - s0) / sec.length + theta[i] / angleScale;
        auto monitor_at = [&](double x) {
            return M[std::lower_bound(s.begin(), s.end(), x - 1e-12 * sec.length) - s.begin()];
        };
        std::vector<double> weights;
        for (size_t j = 0; j + 1 < cuts.size(); ++j) weights.push_back(monitor_at(cuts[j + 1]) - monitor_at(cuts[j]));
        const std::vector<int> counts = element_counts(weights, sec.nElements);
        for (size_t j = 0; j + 1 < cuts.size(); ++j) {
            const double m0 = monitor_at(cuts[j]), m1 = monitor_at(cuts[j + 1]);
            for (int i = 1; i < counts[j]; ++i) {
                // invert M by linear interpolation between the samples
                const double target = m0 + (m1 - m0) * i / counts[j];
                const size_t hi = std::lower_bound(M.begin(), M.end(), target) - M.begin();
                const size_t lo = hi - 1;
                const double f = M[hi] > M[lo] ? (target - M[lo]) / (M[hi] - M[lo]) : 0.0;
                nodes.push_back(s[lo] + f * (s[hi] - s[lo]));
            }
            nodes.push_back(cuts[j + 1]);
        }
    }
    nodes.back() = L;
    return nodes;
}

}  // namespace uc
