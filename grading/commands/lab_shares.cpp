// The labs of one grading shared between its --jobs workers.
#include "grading/commands/lab_shares.hpp"

#include <algorithm>

namespace grading {

// What grading `lab` costs, roughly, to share the labs between the workers:
// a frame for each checkpoint that renders, and a unit check's cases (about
// 200 cost as much as a frame; lab 11 draws thousands).
double grading_cost(const LabData& lab) {
    double cost = 0.0;
    for (const std::vector<Check>& checks : lab.checks) {
        bool renders = false;
        for (const Check& c : checks) {
            renders = renders || c.renders();
            if (c.kind != CheckKind::Unit) continue;
            const UnitCheck& u = c.as<UnitCheck>();
            const size_t cases = u.recorded ? u.recorded->size() : size_t(u.random);
            cost += double(cases + u.edge.size()) / 200.0;
        }
        cost += renders ? 1.0 : 0.0;
    }
    return cost;
}

// The positions in `which` shared between `workers`: the costliest lab first,
// each to the worker with the least cost so far (ties to the lower worker and
// the earlier lab), so that the workers end at about the same time rather
// than one drawing the two slowest labs. Each share keeps the labs' order.
std::vector<std::vector<size_t>> shares(const std::vector<LabData>& labs,
                                        const std::vector<size_t>& which, size_t workers) {
    std::vector<size_t> order(which.size());
    for (size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::vector<double> cost(which.size());
    for (size_t k = 0; k < which.size(); ++k) cost[k] = grading_cost(labs[which[k]]);
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return cost[a] > cost[b]; });
    std::vector<std::vector<size_t>> out(workers);
    std::vector<double> load(workers, 0.0);
    for (size_t k : order) {
        const size_t w = size_t(std::min_element(load.begin(), load.end()) - load.begin());
        out[w].push_back(k);
        load[w] += cost[k];
    }
    for (std::vector<size_t>& share : out) std::sort(share.begin(), share.end());
    return out;
}

}  // namespace grading
