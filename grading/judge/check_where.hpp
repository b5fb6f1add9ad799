// Where a check of checkpoints.json is, for the messages of its validation:
// each names the file, the checkpoint, the check (its number and kind) and
// the field (checks.cpp and the kinds parsed in files of their own).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "grading/judge/checks.hpp"

namespace grading {

class CheckWhere {
public:
    CheckWhere(const LabData& lab, const fw::Checkpoint& cp, size_t index,
               const nlohmann::json& check)
        : lab_(lab), cp_(cp), index_(index), check_(check) {}

    [[noreturn]] void fail(const std::string& field, const std::string& what) const {
        std::string kind =
            check_.is_object() && check_.contains("kind") && check_["kind"].is_string()
                ? " (" + check_["kind"].get<std::string>() + ")"
                : "";
        throw fw::UsageError(lab_.file.path + ": checkpoint '" + cp_.name + "', check " +
                             std::to_string(index_ + 1) + kind +
                             (field.empty() ? ": " : ": \"" + field + "\" ") + what);
    }
    const nlohmann::json& get(const std::string& field) const { return check_[field]; }
    bool has(const std::string& field) const { return check_.contains(field); }

    double number(const std::string& field, double lo, double hi) const {
        const nlohmann::json& v = check_[field];
        if (!v.is_number() || v.get<double>() < lo || v.get<double>() > hi)
            fail(field, "must be a number in [" + nlohmann::json(lo).dump() + ", " +
                            nlohmann::json(hi).dump() + "], got " + v.dump());
        return v.get<double>();
    }
    int integer(const std::string& field, int lo, int hi) const {
        const nlohmann::json& v = check_[field];
        if (!v.is_number_integer() || v.get<long long>() < lo || v.get<long long>() > hi)
            fail(field, "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                            "], got " + v.dump());
        return v.get<int>();
    }
    std::vector<double> numbers(const std::string& field, size_t min_n, size_t max_n, double lo,
                                double hi) const {
        const nlohmann::json& v = check_[field];
        bool ok = v.is_array() && v.size() >= min_n && v.size() <= max_n;
        for (size_t i = 0; ok && i < v.size(); ++i)
            ok = v[i].is_number() && v[i].get<double>() >= lo && v[i].get<double>() <= hi;
        if (!ok)
            fail(field, "must be an array of " + std::to_string(min_n) +
                            (max_n > min_n ? " or " + std::to_string(max_n) : std::string()) +
                            " numbers in [" + nlohmann::json(lo).dump() + ", " +
                            nlohmann::json(hi).dump() + "], got " + v.dump());
        return v.get<std::vector<double>>();
    }

private:
    const LabData& lab_;
    const fw::Checkpoint& cp_;
    size_t index_;
    const nlohmann::json& check_;
};

}  // namespace grading
