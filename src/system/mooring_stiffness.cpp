// mooring_stiffness.cpp - the quasi-static 6x6 stiffness of a mooring system's coupled bodies, the free
// nodes re-balanced (docs/systems_mooring.md, "Mooring stiffness").
//
// The generalized coordinates of body b's stiffness are its pose (6) and those of the free nodes its lines
// reach through free nodes (3 per point, 6 per free body: reference point and a small rotation about the
// earth axes). Their generalized forces are the lines' static end forces (from each line's exact elastic
// catenary, src/model/line_profile.h) and, on a node, its weight, buoyancy and current drag at rest. With J the
// Jacobian of those forces (each line's end forces by central differences in its ends' positions, chained
// through the rigid motion of what they are on), K = -J, and the nodes held in balance to first order
// (dG_f = 0), body b's stiffness is the Schur complement K_cc - K_cf K_ff^-1 K_fc.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "system/mooring_system.h"

namespace uc {

std::vector<MooringSystem::Holder> MooringSystem::stiffness_holders(int b, const UCInputs& in) const {
    const UCCoupledBody& body = in.coupledBody[b - 1];
    std::vector<Holder> holders;
    holders.push_back({-1, 0, 6, Eigen::Map<const Vec3>(body.position),
                       coupled_body_rotation(body, base_.bodyOrientation)});
    // the free nodes a line on body b reaches, directly or through other nodes (not through other coupled
    // bodies: they stay where their inputs put them)
    std::vector<int> nodeHolder(motion_.size(), -1);
    for (bool grown = true; grown;) {
        grown = false;
        for (const MooringDeckLine& l : deck_.lines) {
            const MooringEnd* ends[2] = {&l.fairlead, held_far_end(l)};
            bool held = false;
            for (const MooringEnd* e : ends)
                held = held || (e && stiffness_holder(*e, b, nodeHolder) >= 0);
            if (!held) continue;
            for (const MooringEnd* e : ends) {
                if (!e || e->kind != MooringEnd::Kind::Node || nodeHolder[e->node] >= 0) continue;
                const int n = e->node, dofs = node_unknowns(deck_.nodes[n]);
                nodeHolder[n] = static_cast<int>(holders.size());
                holders.push_back({n, holders.back().offset + holders.back().dofs, dofs, node_position(n), node_rotation(n)});
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

Vec3 MooringSystem::stiffness_place(const MooringEnd& e, int b, const std::vector<Holder>& holders,
                                    const std::vector<int>& nodeHolder, const UCInputs& in) const {
    const int h = stiffness_holder(e, b, nodeHolder);
    if (h < 0) return end_motion(e, in).position;  // an anchor, a coupled point or another body: held
    if (e.kind == MooringEnd::Kind::Node && !deck_.nodes[e.node].body) return holders[h].reference;
    return holders[h].reference + holders[h].rotation * Eigen::Map<const Vec3>(e.position);
}

bool MooringSystem::add_line_jacobian(int k, int b, const std::vector<Holder>& holders,
                                      const std::vector<int>& nodeHolder, const UCInputs& in, Eigen::VectorXd& G,
                                      Eigen::MatrixXd& J, std::string* why) const {
    const MooringDeckLine& l = deck_.lines[k];
    const MooringEnd* ends[2] = {&l.fairlead, held_far_end(l)};
    int h[2];
    Vec3 at[2], on[2];
    for (int e = 0; e < 2; ++e) h[e] = ends[e] ? stiffness_holder(*ends[e], b, nodeHolder) : -1;
    at[0] = stiffness_place(l.fairlead, b, holders, nodeHolder, in);
    at[1] = held_far_end(l) ? stiffness_place(l.far, b, holders, nodeHolder, in) : at[0];
    auto forces = [&](const Vec3 (&x)[2], Vec3 (&f)[2]) -> bool {
        if (profile_end_forces(k, x[0], x[1], f[0], f[1], why)) return true;
        if (why) *why = "mooring line " + std::to_string(l.id) + ": " + *why;
        return false;
    };
    if (!forces(at, on)) return false;
    // D(3 r + i, 3 e + c) = d (force on end r)_i / d (end e)_c, by central differences of the profile
    Eigen::Matrix<double, 6, 6> D = Eigen::Matrix<double, 6, 6>::Zero();
    for (int e = 0; e < 2; ++e) {
        if (h[e] < 0) continue;
        for (int c = 0; c < 3; ++c) {
            Vec3 x[2] = {at[0], at[1]}, fp[2], fm[2];
            x[e][c] = at[e][c] + kStiffnessStep;
            if (!forces(x, fp)) return false;
            x[e][c] = at[e][c] - kStiffnessStep;
            if (!forces(x, fm)) return false;
            for (int r = 0; r < 2; ++r) D.block<3, 1>(3 * r, 3 * e + c) = (fp[r] - fm[r]) / (2.0 * kStiffnessStep);
        }
    }
    // chained through each end's motion with its holder's coordinates, dp = dx - [a]x dtheta (a the arm from
    // the holder's reference point), into the forces and their moments a x f on the holders
    for (int r = 0; r < 2; ++r) {
        if (h[r] < 0) continue;
        const Holder& row = holders[h[r]];
        const Vec3 arm = at[r] - row.reference;
        G.segment<3>(row.offset) += on[r];
        if (row.dofs == 6) {
            G.segment<3>(row.offset + 3) += arm.cross(on[r]);
            J.block<3, 3>(row.offset + 3, row.offset + 3) += skew(on[r]) * skew(arm);  // the arm turns with it
        }
        for (int e = 0; e < 2; ++e) {
            if (h[e] < 0) continue;
            const Holder& col = holders[h[e]];
            Eigen::Matrix<double, 3, 6> dF;
            dF.leftCols<3>() = D.block<3, 3>(3 * r, 3 * e);
            dF.rightCols<3>() = -D.block<3, 3>(3 * r, 3 * e) * skew(at[e] - col.reference);
            J.block(row.offset, col.offset, 3, col.dofs) += dF.leftCols(col.dofs);
            if (row.dofs == 6) J.block(row.offset + 3, col.offset, 3, col.dofs) += (skew(arm) * dF).leftCols(col.dofs);
        }
    }
    return true;
}

void MooringSystem::add_node_loads(const Holder& holder, const UCInputs& in, Eigen::VectorXd& G) const {
    if (holder.dofs == 6) {  // a free body's loads at rest (body_load: weight and buoyancy at its centre of gravity)
        Vec3 force, moment;
        body_load(holder.node, holder.reference, holder.rotation, Vec3::Zero(), Vec3::Zero(), in, force, moment);
        G.segment<3>(holder.offset) += force;
        G.segment<3>(holder.offset + 3) += moment;
        return;
    }
    G.segment<3>(holder.offset) += node_load(holder.node, holder.reference, in);  // at rest
}

bool MooringSystem::body_stiffness(int b, const UCInputs& in, double K[36], std::string* why) const {
    for (int i = 0; i < 36; ++i) K[i] = 0.0;
    for (const MooringNode& node : deck_.nodes) {
        if (!node.pinned) continue;
        if (why) *why = "the stiffness of a system with a pinned body (body " + std::to_string(node.point.id) + ") is not "
                        "computed";
        return false;
    }
    std::vector<Holder> holders = stiffness_holders(b, in);
    std::vector<int> nodeHolder(motion_.size(), -1);
    for (size_t h = 1; h < holders.size(); ++h) nodeHolder[holders[h].node] = static_cast<int>(h);
    const int n = holders.back().offset + holders.back().dofs;
    std::vector<int> lines;  // with an end on a holder
    for (size_t k = 0; k < lines_.size(); ++k) {
        const MooringDeckLine& l = deck_.lines[k];
        if (stiffness_holder(l.fairlead, b, nodeHolder) >= 0 || (held_far_end(l) && stiffness_holder(l.far, b, nodeHolder) >= 0))
            lines.push_back(static_cast<int>(k));
    }
    // G (the nodes' unbalanced forces G_f among them) and J = dG/dq where the holders stand: each line's
    // end forces differenced in its ends' positions and chained through the holders' motion; a node's own
    // loads (a free body's weight turns with it) differenced in its coordinates
    Eigen::MatrixXd J(n, n);
    Eigen::VectorXd G(n), Gp(n), Gm(n);
    auto jacobian = [&]() -> bool {
        J.setZero();
        G.setZero();
        for (size_t h = 1; h < holders.size(); ++h) {
            const Holder rest = holders[h];
            add_node_loads(rest, in, G);
            for (int j = 0; j < rest.dofs; ++j) {
                const double d = j < 3 ? kStiffnessStep : kStiffnessAngle;
                for (int sign : {1, -1}) {
                    Holder moved = rest;
                    if (j < 3)
                        moved.reference[j] += sign * d;
                    else
                        moved.rotation = turn_matrix(sign * d * Vec3::Unit(j - 3)) * rest.rotation;
                    Eigen::VectorXd& out = sign > 0 ? Gp : Gm;
                    out.setZero();
                    add_node_loads(moved, in, out);
                }
                J.col(rest.offset + j) += (Gp - Gm) / (2.0 * d);
            }
        }
        for (int k : lines)
            if (!add_line_jacobian(k, b, holders, nodeHolder, in, G, J, why)) return false;
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

bool MooringSystem::update_stiffness(UCOutputs& out, std::string&) {
    update_stiffness();
    for (int b = 0; b < UC_MAX_BODIES; ++b)
        std::memcpy(out.bodyLoad[b].stiffness, outputs_.bodyLoad[b].stiffness, sizeof out.bodyLoad[b].stiffness);
    return true;
}

}  // namespace uc
