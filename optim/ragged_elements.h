#pragma once
// The elements of a term of run-time arity (optim/dynamic_element_energy.h): element e names
// arity(e) variable indices, and every element's indices are stored back to back, so that one
// term holds fans, rings or stars of any size.
//
//   sa::RaggedElements fans;
//   fans.push_back({v0, v1, v2, v3});             // an element of four variables
//   fans.push_back(std::span<const sa::Index>(ids));  // or of ids.size()

#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <vector>

#include "optim/types.h"

namespace sa {

class RaggedElements {
  public:
    RaggedElements() : offsets_{0} {}

    /// Appends an element naming `variables`, in that order.
    void push_back(std::span<const Index> variables) {
        indices_.insert(indices_.end(), variables.begin(), variables.end());
        offsets_.push_back(static_cast<std::int64_t>(indices_.size()));
        max_arity_ = std::max(max_arity_, static_cast<int>(variables.size()));
    }
    void push_back(std::initializer_list<Index> variables) {
        push_back(std::span<const Index>(variables.begin(), variables.size()));
    }
    /// Room for `elements` elements naming `indices` variables in all.
    void reserve(Index elements, std::int64_t indices) {
        offsets_.reserve(std::size_t(elements) + 1);
        indices_.reserve(std::size_t(indices));
    }

    Index size() const { return static_cast<Index>(offsets_.size() - 1); }
    bool empty() const { return size() == 0; }
    /// The number of variables element e names.
    int arity(Index e) const { return static_cast<int>(offsets_[e + 1] - offsets_[e]); }
    /// The largest arity (0 when empty).
    int max_arity() const { return max_arity_; }
    /// The variables of element e.
    std::span<const Index> operator[](Index e) const {
        return {indices_.data() + offsets_[e], std::size_t(arity(e))};
    }

    /// Every element's variables back to back, and where each element's begin: offsets()[e] to
    /// offsets()[e + 1] (size() + 1 entries, the first 0).
    const std::vector<Index>& indices() const { return indices_; }
    const std::vector<std::int64_t>& offsets() const { return offsets_; }

  private:
    std::vector<Index> indices_;
    std::vector<std::int64_t> offsets_;
    int max_arity_ = 0;
};

}  // namespace sa
