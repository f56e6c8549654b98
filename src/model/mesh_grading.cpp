// mesh_grading.cpp - nodes graded by the static profile (mesh_grading.h).
#include "model/mesh_grading.h"

#include <algorithm>
#include <cmath>

namespace uc {
namespace {

constexpr int kSamples = 4096;  // per section, to integrate and invert the monitor M(s)
constexpr double kTinyTension = 1e-9;  // [N] floor of the tension whose logarithm grades

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

std::vector<double> graded_nodes(const CableModel& model, const LineProfile& profile, bool towOnTop,
                                 bool alongLine, const GradingWeights& weights) {
    const double L = model.line().length;
    auto turning = [&](double s) {  // from the tow point, whichever end the profile starts at
        return towOnTop ? profile.turning(s) : profile.turning(L) - profile.turning(L - s);
    };
    auto profile_tension = [&](double s) { return towOnTop ? profile.tension(s) : profile.tension(L - s); };
    std::vector<double> contacts = profile.contacts();  // where the line reaches or leaves the seabed
    for (double& c : contacts) c = towOnTop ? c : L - c;
    std::vector<double> nodes{0.0};
    // Grades [s0, s1] with n elements: `fixed` must be nodes (the ends, attachments, section ends
    // inside), the contacts become nodes unless they lie within `minimum` of another cut.
    auto grade = [&](double s0, double s1, int n, std::vector<double> fixed) {
        const double minimum = 1e-3 * (s1 - s0) / n;  // closer cuts merge
        std::vector<double> cuts{s0, s1};
        auto near_a_cut = [&](double x) {
            return std::any_of(cuts.begin(), cuts.end(), [&](double c) { return std::abs(x - c) <= minimum; });
        };
        for (double f : fixed)
            if (f > s0 && f < s1 && !near_a_cut(f)) cuts.push_back(f);
        for (double c : contacts)
            if (c > s0 && c < s1 && !near_a_cut(c)) cuts.push_back(c);
        std::sort(cuts.begin(), cuts.end());
        // the monitor on a fine grid with every cut on it, denser towards the cuts (geometric
        // steps from each end resolve a touchdown whose H / w is far below the uniform step)
        std::vector<double> s, theta, logT;
        std::vector<size_t> pieceOf;  // the piece between cuts each sample lies in
        for (size_t j = 0; j + 1 < cuts.size(); ++j) {
            const double a = cuts[j], b = cuts[j + 1];
            const int m = std::max(8, static_cast<int>(kSamples * (b - a) / (s1 - s0)));
            std::vector<double> piece;
            for (int i = 0; i < m; ++i) piece.push_back(a + (b - a) * i / m);
            for (double d = (b - a) / m / 2; d > 1e-7 * (b - a); d /= 2) {
                piece.push_back(a + d);
                piece.push_back(b - d);
            }
            std::sort(piece.begin(), piece.end());
            s.insert(s.end(), piece.begin(), piece.end());
            pieceOf.insert(pieceOf.end(), piece.size(), j);
        }
        s.push_back(s1);
        pieceOf.push_back(cuts.size() - 2);
        double turned = 0.0, previous = turning(s0);
        // the tension's logarithm, counted inside each piece only (it jumps at a point load's cut)
        double stretched = 0.0, previousLog = 0.0;
        for (size_t i = 0; i < s.size(); ++i) {
            const double t = turning(s[i]);
            turned += std::abs(t - previous);
            previous = t;
            theta.push_back(turned);
            const double l = std::log(std::max(profile_tension(s[i]), kTinyTension));
            // not from a cut: a point load there makes the tension on its two sides differ
            if (i > 0 && pieceOf[i] == pieceOf[i - 1] && s[i - 1] != cuts[pieceOf[i]])
                stretched += std::abs(l - previousLog);
            previousLog = l;
            logT.push_back(stretched);
        }
        const double angleScale = std::max(turned, kGradingAngle) / weights.angle;
        const double logScale = std::max(stretched / weights.logTensionWeight, weights.logTension);
        std::vector<double> M(s.size());
        for (size_t i = 0; i < s.size(); ++i)
            M[i] = (s[i] - s0) / (s1 - s0) + theta[i] / angleScale + logT[i] / logScale;
        auto monitor_at = [&](double x) {
            return M[std::lower_bound(s.begin(), s.end(), x - 1e-12 * (s1 - s0)) - s.begin()];
        };
        std::vector<double> weights;
        for (size_t j = 0; j + 1 < cuts.size(); ++j) weights.push_back(monitor_at(cuts[j + 1]) - monitor_at(cuts[j]));
        const std::vector<int> counts = element_counts(weights, n);
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
    };
    std::vector<double> attachments;
    for (const NodeAttachment& at : model.attachments()) attachments.push_back(at.s);
    if (alongLine) {
        // one monitor along the whole line, every section end a node; the elements of all sections
        std::vector<double> fixed = attachments;
        int total = 0;
        for (int k = 0; k < model.n_sections(); ++k) {
            total += model.section(k).nElements;
            if (k > 0) fixed.push_back(model.section(k).s0);
        }
        grade(0.0, L, std::max(total, model.n_sections()), fixed);
    } else {
        for (int k = 0; k < model.n_sections(); ++k) {
            const SectionProps& sec = model.section(k);
            grade(sec.s0, sec.s0 + sec.length, sec.nElements, attachments);
        }
    }
    nodes.back() = L;
    return nodes;
}

}  // namespace uc
