#include "lib/scenario/read_tearing.hpp"

#include <limits>

namespace tissu {
namespace {

const NumberRule weakening_factor{0.0, 1.0, true, "a number in (0, 1]"};

WeakRegion read_weak_region(JsonObjectReader o) {
  WeakRegion region;
  if (o.has("line") == o.has("box")) o.fail("line", "exactly one of \"line\" and \"box\"");
  if (o.has("line")) {
    region.kind = WeakRegion::Kind::line;
    region.points_m = o.points("line", 2);
    region.width_m = o.number("width", positive(" (m)"));
  } else {
    region.kind = WeakRegion::Kind::box;
    region.box = o.box("box");
  }
  region.factor = o.number("factor", weakening_factor);
  o.finish();
  return region;
}

ScriptedCut read_cut(JsonObjectReader o, double after_s) {
  ScriptedCut cut;
  cut.time_s = o.number("time", non_negative(" (s)"));
  if (cut.time_s < after_s) {
    o.fail("time", "a time not before the previous cut's " + std::to_string(after_s) + " s");
  }
  cut.points_m = o.points("line", 2);
  o.finish();
  return cut;
}

}  // namespace

TearingSettings read_tearing(JsonObjectReader tearing) {
  TearingSettings t;
  TearingOptions& o = t.options;
  t.enabled = tearing.boolean_or("enabled", true);
  o.strain_threshold = tearing.number_or("strain", 0.0, non_negative(""));
  o.max_tears_per_step = tearing.integer_or("max_tears_per_step", o.max_tears_per_step, 1,
                                            std::numeric_limits<int>::max());
  o.min_piece_faces =
      tearing.integer_or("min_piece_faces", o.min_piece_faces, 1, std::numeric_limits<int>::max());
  o.tip_min_edge_length_m =
      tearing.number_or("tip_min_edge_length", o.tip_min_edge_length_m, non_negative(" (m)"));
  if (tearing.has("weak_regions")) {
    for (const ArrayElement& element : tearing.array("weak_regions")) {
      o.weak_regions.push_back(read_weak_region(object_reader(element, tearing.file())));
    }
  }
  if (tearing.has("cuts")) {
    for (const ArrayElement& element : tearing.array("cuts")) {
      const double after_s = t.cuts.empty() ? 0.0 : t.cuts.back().time_s;
      t.cuts.push_back(read_cut(object_reader(element, tearing.file()), after_s));
    }
  }
  tearing.finish();  // a misspelt key first: it may be why nothing tears
  if (t.enabled && o.strain_threshold == 0.0 && t.cuts.empty()) {
    tearing.fail("strain", "a positive \"strain\" or at least one of \"cuts\" when tearing");
  }
  return t;
}

}  // namespace tissu
