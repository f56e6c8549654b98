// mooring_stiffness.cpp - the quasi-static 6x6 stiffness of a mooring system's coupled bodies, the free
// nodes re-balanced (docs/systems_mooring.md, "Mooring stiffness").
//
// The generalized coordinates of body b's stiffness are its pose (6) and those of the free nodes its lines
// reach through free nodes (3 per point, 6 per free body: reference point and a small rotation about the
// earth axes). Their generalized forces are the lines' static end forces (from each line's exact elastic
// catenary, src/line_profile.h) and, on a node, its weight, buoyancy and current drag at rest. With J the
// Jacobian of those forces (central differences), K = -J, and the nodes held in balance to first order
// (dG_f = 0), body b's stiffness is the Schur complement K_cc - K_cf K_ff^-1 K_fc.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "mooring_system.h"

namespace uc {
namespace {

Mat3 turn_matrix(const Vec3& turn) {  // the rotation by |turn| about turn (a rotation vector)
    const double angle = turn.norm();
    return Eigen::AngleAxisd(angle, angle > 0.0 ? Vec3(turn / angle) : Vec3::UnitX()).toRotationMatrix();
}

}  // namespace

std::vector<MooringSystem::Holder> MooringSystem::stiffness_holders(int b, const UCInputs& in) const {
    const UCCoupledBody& body = in.coupledBody[b - 1];
    std::vector<Holder> holders;
    holders.push_back({-1, 0, 6, Eigen::Map<const Vec3>(body.position),
                       body_rotation(body.rotation[0], body.rotation[1], body.rotation[2])});
    // the free nodes a line on body b reaches, directly or through other nodes (not through other coupled
    // bodies: they stay where their inputs put them)
    std::vector<int> nodeHolder(nodes_.size(), -1);
    for (bool grown = true; grown;) {
        grown = false;
        for (const MooringDeckLine& l : deck_.lines) {
            const MooringEnd* ends[2] = {&l.fairlead, l.farFree ? nullptr : &l.far};
            bool held = false;
            for (const MooringEnd* e : ends)
                held = held || (e && stiffness_holder(*e, b, nodeHolder) >= 0);
            if (!held) continue;
            for (const MooringEnd* e : ends) {
                if (!e || e->kind != MooringEnd::Kind::Node || nodeHolder[e->node] >= 0) continue;
                const int n = e->node, dofs = deck_.nodes[n].body ? 6 : 3;
                nodeHolder[n] = static_cast<int>(holders.size());
                holders.push_back({n, holders.back().offset + holders.back().dofs, dofs, nodes_[n], nodeRotation_[n]});
                grown = true;
            }
        }
    }
    return holders;
}

int MooringSystem::stiffness_holder(const MooringEnd& e, int b, const std::vector<int>& nodeHolder) const {
    if (e.kind == MooringEnd::Kind::Body) return e.body == b ? 0 : -1;
    if (e.kind == MooringEnd::Kind::Node) return nodeHolder[e.node];
    return -1;
}

bool MooringSystem::add_stiffness_loads(int k, int b, const std::vector<Holder>& holders,
                                        const std::vector<int>& nodeHolder, const UCInputs& in, Eigen::VectorXd& G,
                                        std::string* why) const {
    const MooringDeckLine& l = deck_.lines[k];
    auto place = [&](const MooringEnd& e) -> Vec3 {
        const int h = stiffness_holder(e, b, nodeHolder);
        if (h < 0) return end_motion(e, in).position;  // an anchor, a coupled point or another body: held
        if (e.kind == MooringEnd::Kind::Node && !deck_.nodes[e.node].body) return holders[h].reference;
        return holders[h].reference + holders[h].rotation * Eigen::Map<const Vec3>(e.position);
    };
    const Vec3 at[2] = {place(l.fairlead), l.farFree ? place(l.fairlead) : place(l.far)};
    Vec3 on[2];
    if (!profile_end_forces(k, at[0], at[1], on[0], on[1], why)) {
        if (why) *why = "mooring line " + std::to_string(l.id) + ": " + *why;
        return false;
    }
    const MooringEnd* ends[2] = {&l.fairlead, l.farFree ? nullptr : &l.far};
    for (int e = 0; e < 2; ++e) {
        const int h = ends[e] ? stiffness_holder(*ends[e], b, nodeHolder) : -1;
        if (h < 0) continue;
        const Holder& holder = holders[h];
        G.segment<3>(holder.offset) += on[e];
        if (holder.dofs == 6) G.segment<3>(holder.offset + 3) += (at[e] - holder.reference).cross(on[e]);
    }
    return true;
}

void MooringSystem::add_node_loads(const Holder& holder, const UCInputs& in, Eigen::VectorXd& G) const {
    const MooringNode& node = deck_.nodes[holder.node];
    G.segment<3>(holder.offset) += node_load(holder.node, holder.reference, in);  // at rest
    if (holder.dofs == 6) {  // a free body's weight at its centre of gravity (buoyancy and drag at its reference)
        const double g = lines_[0]->model().fluid().gravity;
        G.segment<3>(holder.offset + 3) +=
            (holder.rotation * Eigen::Map<const Vec3>(node.cg)).cross(Vec3(0.0, 0.0, -node.point.mass * g));
    }
}

bool MooringSystem::body_stiffness(int b, const UCInputs& in, double K[36], std::string* why) const {
    for (int i = 0; i < 36; ++i) K[i] = 0.0;
    std::vector<Holder> holders = stiffness_holders(b, in);
    std::vector<int> nodeHolder(nodes_.size(), -1);
    for (size_t h = 1; h < holders.size(); ++h) nodeHolder[holders[h].node] = static_cast<int>(h);
    const int n = holders.back().offset + holders.back().dofs;
    // the lines with an end on a holder, and their holders
    std::vector<int> lines;
    std::vector<std::array<int, 2>> lineHolders;
    for (size_t k = 0; k < lines_.size(); ++k) {
        const MooringDeckLine& l = deck_.lines[k];
        const std::array<int, 2> h = {stiffness_holder(l.fairlead, b, nodeHolder),
                                      l.farFree ? -1 : stiffness_holder(l.far, b, nodeHolder)};
        if (h[0] < 0 && h[1] < 0) continue;
        lines.push_back(static_cast<int>(k));
        lineHolders.push_back(h);
    }
    // J = dG/dq column by column: a holder's coordinate moved both ways, the loads that move with it; and
    // G_f, the nodes' unbalanced forces, where they stand
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd G(n), Gp(n), Gm(n);
    auto loads = [&](int moved, Eigen::VectorXd& out) -> bool {
        out.setZero();
        for (size_t h = 1; h < holders.size(); ++h)
            if (moved < 0 || static_cast<int>(h) == moved) add_node_loads(holders[h], in, out);
        for (size_t i = 0; i < lines.size(); ++i) {
            if (moved >= 0 && lineHolders[i][0] != moved && lineHolders[i][1] != moved) continue;
            if (!add_stiffness_loads(lines[i], b, holders, nodeHolder, in, out, why)) return false;
        }
        return true;
    };
    auto jacobian = [&]() -> bool {
        for (size_t h = 0; h < holders.size(); ++h) {
            const Holder rest = holders[h];
            for (int j = 0; j < rest.dofs; ++j) {
                const double d = j < 3 ? kStiffnessStep : kStiffnessAngle;
                for (int sign : {1, -1}) {
                    holders[h] = rest;
                    if (j < 3)
                        holders[h].reference[j] += sign * d;
                    else
                        holders[h].rotation = turn_matrix(sign * d * Vec3::Unit(j - 3)) * rest.rotation;
                    if (!loads(static_cast<int>(h), sign > 0 ? Gp : Gm)) return false;
                }
                holders[h] = rest;
                J.col(rest.offset + j) = (Gp - Gm) / (2.0 * d);
            }
        }
        return true;
    };
    if (!jacobian()) return false;
    const int m = n - 6;
    Eigen::FullPivLU<Eigen::MatrixXd> lu;
    double move = HUGE_VAL;
    // The nodes re-balanced on the lines' profiles: Newton's method from where they stand (their static
    // equilibrium on the lines' finite elements, or their motion) to where the profiles hold them at rest
    // with the body at its pose; the Jacobian at the last point is the one condensed.
    for (int it = 0; m > 0; ++it) {
        lu.compute(J.bottomRightCorner(m, m));
        if (!lu.isInvertible()) {
            if (why) *why = "the stiffness of the free nodes its lines reach is singular";
            return false;
        }
        if (!loads(-1, G)) return false;
        Eigen::VectorXd dx = -lu.solve(G.tail(m));
        // converged when a step moves the nodes by less than kStiffnessBalance (m, rad), or by little more
        // where the steps stop shrinking (the profiles' own tolerance)
        const double last = move;
        move = dx.lpNorm<Eigen::Infinity>();
        if (move < kStiffnessBalance || (move < 100.0 * kStiffnessBalance && move > 0.5 * last)) break;
        if (it == kNodeIterations) {
            if (why)
                *why = "the free nodes its lines reach do not come to rest on the lines' profiles (last step " +
                       std::to_string(move) + " m)";
            return false;
        }
        double shrink = 1.0;  // a node moves by at most kStiffnessReach, a body turns by at most kMaxTurn
        for (size_t h = 1; h < holders.size(); ++h) {
            const int o = holders[h].offset - 6;
            shrink = std::min(shrink, kStiffnessReach / std::max(dx.segment<3>(o).lpNorm<Eigen::Infinity>(), 1e-300));
            if (holders[h].dofs == 6)
                shrink = std::min(shrink, kMaxTurn / std::max(dx.segment<3>(o + 3).lpNorm<Eigen::Infinity>(), 1e-300));
        }
        dx *= shrink;
        for (size_t h = 1; h < holders.size(); ++h) {
            Holder& node = holders[h];
            node.reference += dx.segment<3>(node.offset - 6);
            if (node.dofs == 6) node.rotation = turn_matrix(dx.segment<3>(node.offset - 3)) * node.rotation;
        }
        if (!jacobian()) return false;
    }
    Eigen::Matrix<double, 6, 6> Kb = -J.topLeftCorner<6, 6>();
    if (m > 0)  // the free nodes' coordinates condensed: K = K_cc - K_cf K_ff^-1 K_fc with K = -J
        Kb += J.topRightCorner(6, m) * lu.solve(J.bottomLeftCorner(m, 6));
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) K[6 * i + j] = Kb(i, j);
    return true;
}

void MooringSystem::update_stiffness() {
    if (stiffnessCurrent_) return;
    stiffnessCurrent_ = true;
    for (int b = 1; b <= deck_.bodies; ++b) {
        std::string why;
        if (body_stiffness(b, lastInputs_, outputs_.bodyLoad[b - 1].stiffness, &why)) continue;
        std::memset(outputs_.bodyLoad[b - 1].stiffness, 0, sizeof outputs_.bodyLoad[b - 1].stiffness);
        if (!stiffnessWarned_) {
            stiffnessWarned_ = true;
            event_ = "body[" + std::to_string(b) + "].stiffness is 0 from t = " + std::to_string(time()) +
                     " s (reported once): " + why;
        }
    }
}

}  // namespace uc
