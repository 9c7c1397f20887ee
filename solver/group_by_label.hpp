#pragma once
/// \file
/// Items grouped by a label, as compressed rows (internal).

#include <vector>

namespace tissu {

/// A counting sort of the items 0 .. label.size() - 1 by their label in [0, groups): group g's
/// items, ascending, are ids[offsets[g], offsets[g + 1]). Items labelled < 0 are left out.
inline void group_by_label(const std::vector<int>& label, int groups, std::vector<int>& offsets,
                           std::vector<int>& ids) {
  offsets.assign(groups + 1, 0);
  for (int g : label) {
    if (g >= 0) ++offsets[g + 1];
  }
  for (int g = 0; g < groups; ++g) offsets[g + 1] += offsets[g];
  ids.resize(offsets[groups]);
  std::vector<int> next(offsets.begin(), offsets.end() - 1);
  for (int i = 0; i < static_cast<int>(label.size()); ++i) {
    if (label[i] >= 0) ids[next[label[i]]++] = i;
  }
}

}  // namespace tissu
