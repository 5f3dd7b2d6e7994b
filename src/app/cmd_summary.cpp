// pound summary --input RUN.h5 [--floors] [--json]: the amplification statistics of a campaign
// file (/amplification, campaign/amplification_file.hpp) as a compact table, the collapse shares
// when the file has them, then the same per contact model where the study samples it. The file
// is opened read-only; one written before /amplification existed (or before its collapse shares
// and per-model tables) gets it computed in memory.
#include <hdf5.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/help.hpp"
#include "app/table_number.hpp"
#include "campaign/amplification_file.hpp"
#include "core/error.hpp"
#include "fragility/campaign_reader.hpp"
#include "io/h5.hpp"
#include "io/json.hpp"
#include "io/options.hpp"
#include "motion/ground_motion.hpp"

namespace pound::app {
namespace {

// "median [p16, p84] share" of one floor.
std::string cell(const AmplificationMeasure& m, std::size_t at) {
  if (m.count[at] == 0) return "-";
  return fmt("%.3f", m.median[at]) + " [" + fmt("%.3f", m.p16[at]) + ", " + fmt("%.3f", m.p84[at]) +
         "] " + fmt("%.2f", m.fraction_above_1[at]);
}

// The floors shown of group g and building b: every floor, or per measure the one with the
// largest median.
std::vector<std::vector<std::size_t>> shown_floors(const AmplificationTable& t, std::size_t g,
                                                   std::size_t b, bool floors) {
  std::vector<std::vector<std::size_t>> rows;
  if (floors) {
    for (std::size_t f = 0; f < t.floors; ++f) rows.push_back({f, f, f});
    return rows;
  }
  std::vector<std::size_t> pick;
  for (const auto& m : t.measures) {
    std::size_t best = 0;
    double top = -1.0;
    for (std::size_t f = 0; f < t.floors; ++f) {
      const double x = m.median[t.at(g, b, f)];
      if (m.count[t.at(g, b, f)] > 0 && x > top) top = x, best = f;
    }
    pick.push_back(best);
  }
  rows.push_back(pick);
  return rows;
}

void print_measures(const AmplificationTable& t, const std::vector<std::string>& names,
                    const std::string& im, bool floors) {
  std::printf("  %-5s %9s %5s %5s  %-10s %-6s %-30s %-6s %-30s %-6s %-30s\n", "group",
              (im + " [g]").c_str(), "n", "fail", "building", "floor", "disp", "storey", "drift",
              "floor", "accel");
  for (std::size_t g = 0; g < t.groups; ++g)
    for (std::size_t b = 0; b < t.buildings; ++b)
      for (const auto& r : shown_floors(t, g, b, floors)) {
        bool any = false;
        for (std::size_t k = 0; k < 3; ++k) any |= t.measures[k].count[t.at(g, b, r[k])] > 0;
        if (!any) continue;  // a floor the building does not have
        std::printf("  %-5zu %9s %5ld %5ld  %-10s", g + 1, fmt("%.4g", t.im[g] / kGravity).c_str(),
                    t.samples[g], t.failed[g], names[b].c_str());
        for (std::size_t k = 0; k < 3; ++k)
          std::printf(" %-6zu %-30s", r[k] + 1, cell(t.measures[k], t.at(g, b, r[k])).c_str());
        std::printf("\n");
      }
}

void print_contacts(const AmplificationTable& t, const std::string& im) {
  std::printf(
      "\nContacts: share of samples that pounded at each level, median peak force over all "
      "samples and over those that pounded [kN]\n");
  std::printf("  %-5s %9s  %-5s %-6s %9s %12s %14s\n", "group", (im + " [g]").c_str(), "pair",
              "level", "pounded", "force [kN]", "if pounded");
  for (std::size_t g = 0; g < t.groups; ++g)
    for (std::size_t p = 0; p < t.pairs; ++p)
      for (std::size_t l = 0; l < t.levels; ++l) {
        const std::size_t at = t.site(g, p, l);
        if (t.contact_count[at] == 0) continue;
        std::printf("  %-5zu %9s  %-5zu %-6zu %9s %12s %14s\n", g + 1,
                    fmt("%.4g", t.im[g] / kGravity).c_str(), p + 1, l + 1,
                    fmt("%.3f", t.pounded_fraction[at]).c_str(),
                    fmt("%.4g", t.force_median[at] / 1e3).c_str(),
                    fmt("%.4g", t.force_median_pounded[at] / 1e3).c_str());
      }
}

void print_collapse(const AmplificationTable& t, const std::vector<std::string>& names,
                    const std::string& im) {
  if (!t.has_collapse) return;
  std::printf(
      "\nCollapse: share of the successful samples (n) whose building collapsed, with and "
      "without pounding\n"
      "(the pounding run stops at the row's first collapse: 'stopped' is the share still standing "
      "then beside a collapsed neighbour, their fate unknown; 'of the rest' = pounding / (1 - "
      "stopped), as pound fragility counts them)\n");
  std::printf("  %-5s %9s %5s  %-10s %9s %9s %11s %9s\n", "group", (im + " [g]").c_str(), "n",
              "building", "pounding", "stopped", "of the rest", "free");
  for (std::size_t g = 0; g < t.groups; ++g)
    for (std::size_t b = 0; b < t.buildings; ++b) {
      const std::size_t at = t.building_at(g, b);
      const double stopped = t.stopped_pounding.empty() ? NAN : t.stopped_pounding[at];
      std::printf("  %-5zu %9s %5ld  %-10s %9s %9s %11s %9s\n", g + 1,
                  fmt("%.4g", t.im[g] / kGravity).c_str(), t.collapse_count[at], names[b].c_str(),
                  fmt("%.3f", t.collapsed_pounding[at]).c_str(), fmt("%.3f", stopped).c_str(),
                  fmt("%.3f", stopped < 1 ? t.collapsed_pounding[at] / (1 - stopped) : NAN).c_str(),
                  fmt("%.3f", t.collapsed_free[at]).c_str());
    }
}

// Issue 36: the share of samples whose struck columns failed in shear (ratio >= 1).
void print_column_shear(const AmplificationTable& t, const std::vector<std::string>& names,
                        const std::string& im) {
  if (!t.has_column_shear) return;
  std::printf(
      "\nColumn shear: share of the samples (n, those with a column_shear_strength and a struck "
      "storey) whose struck columns' shear demand reached their strength, with and without "
      "pounding\n");
  std::printf("  %-5s %9s %5s  %-10s %9s %9s\n", "group", (im + " [g]").c_str(), "n", "building",
              "pounding", "free");
  for (std::size_t g = 0; g < t.groups; ++g)
    for (std::size_t b = 0; b < t.buildings; ++b) {
      const std::size_t at = t.building_at(g, b);
      if (t.column_shear_count[at] == 0) continue;
      std::printf("  %-5zu %9s %5ld  %-10s %9s %9s\n", g + 1,
                  fmt("%.4g", t.im[g] / kGravity).c_str(), t.column_shear_count[at],
                  names[b].c_str(), fmt("%.3f", t.column_shear_failed_pounding[at]).c_str(),
                  fmt("%.3f", t.column_shear_failed_free[at]).c_str());
    }
}

// The tables of one table (every sample, or one contact model's).
void print_tables(const AmplificationTable& t, const std::vector<std::string>& names,
                  const std::string& im, bool floors) {
  print_measures(t, names, im, floors);
  print_contacts(t, im);
  print_collapse(t, names, im);
  print_column_shear(t, names, im);
  if (t.failed_total)
    std::printf("\n(%ld failed samples are counted in n and fail, not used)\n", t.failed_total);
}

// computed: why the statistics were computed now ("" when they were read from the file).
void print_text(const AmplificationTable& t, const std::vector<std::string>& names,
                const std::string& measure, bool floors, const std::string& computed) {
  const std::string im = measure == "sa" ? "Sa(T1)" : "PGA";
  std::printf(
      "Amplification by pounding, peak with / peak without: median [16 %%, 84 %%] and share of "
      "samples above 1\n(%s; %s%s)\n",
      t.stripes ? (im + " stripes").c_str() : (im + " bins of equal count").c_str(),
      floors ? "every floor" : "per building the floor (storey for drift) whose median is largest",
      computed.empty() ? "" : ("; " + computed).c_str());
  std::string labels;
  for (const auto& m : t.models) labels += (labels.empty() ? "" : ", ") + m.model;
  if (!t.models.empty())
    std::printf("All samples, pooled over the contact models (%s); each model's tables follow\n",
                labels.c_str());
  print_tables(t, names, im, floors);
  for (const auto& m : t.models) {
    long n = 0;
    for (long x : m.samples) n += x;
    std::printf("\n== Contact model %s (/samples/model): %ld samples, in the same %s\n",
                m.model.c_str(), n, t.stripes ? "stripes" : "IM bins");
    print_tables(m, names, im, floors);
  }
}

// The "groups" array of one table.
void json_groups(JsonWriter& w, const AmplificationTable& t) {
  w.key("groups").begin_array();
  for (std::size_t g = 0; g < t.groups; ++g) {
    w.begin_object().field("im", t.im[g]).field("im_lo", t.im_lo[g]).field("im_hi", t.im_hi[g]);
    w.field("samples", t.samples[g]).field("failed", t.failed[g]);
    w.key("buildings").begin_array();
    for (std::size_t b = 0; b < t.buildings; ++b) {
      w.begin_object().field("building", long(b)).key("floors").begin_array();
      for (std::size_t f = 0; f < t.floors; ++f) {
        const std::size_t at = t.at(g, b, f);
        w.begin_object().field("floor", long(f + 1));
        for (const auto& m : t.measures)
          w.key(m.name)
              .begin_object()
              .field("count", m.count[at])
              .field("mean", m.mean[at])
              .field("median", m.median[at])
              .field("p16", m.p16[at])
              .field("p84", m.p84[at])
              .field("fraction_above_1", m.fraction_above_1[at])
              .end_object();
        w.end_object();
      }
      w.end_array().end_object();
    }
    w.end_array();
    w.key("contacts").begin_array();
    for (std::size_t p = 0; p < t.pairs; ++p)
      for (std::size_t l = 0; l < t.levels; ++l) {
        const std::size_t at = t.site(g, p, l);
        w.begin_object().field("pair", long(p + 1)).field("level", long(l + 1));
        w.field("count", t.contact_count[at]).field("pounded_fraction", t.pounded_fraction[at]);
        w.field("force_median_N", t.force_median[at]);
        w.field("force_median_pounded_N", t.force_median_pounded[at]).end_object();
      }
    w.end_array();
    if (t.has_collapse) {
      w.key("collapse").begin_array();
      for (std::size_t b = 0; b < t.buildings; ++b) {
        const std::size_t at = t.building_at(g, b);
        w.begin_object().field("building", long(b)).field("count", t.collapse_count[at]);
        w.field("collapsed_pounding", t.collapsed_pounding[at]);
        w.field("stopped_pounding", t.stopped_pounding.empty() ? NAN : t.stopped_pounding[at]);
        w.field("collapsed_free", t.collapsed_free[at]).end_object();
      }
      w.end_array();
    }
    if (t.has_column_shear) {  // issue 36
      w.key("column_shear").begin_array();
      for (std::size_t b = 0; b < t.buildings; ++b) {
        const std::size_t at = t.building_at(g, b);
        w.begin_object().field("building", long(b)).field("count", t.column_shear_count[at]);
        w.field("failed_pounding", t.column_shear_failed_pounding[at]);
        w.field("failed_free", t.column_shear_failed_free[at]).end_object();
      }
      w.end_array();
    }
    w.end_object();
  }
  w.end_array();
}

void print_json(const AmplificationTable& t, const std::string& input,
                const std::vector<std::string>& names, bool computed) {
  JsonWriter w;
  w.begin_object().field("input", input).field("design", t.stripes ? "stripes" : "bins");
  w.field("computed_now", computed).field("failed", t.failed_total).field("im_units", "m/s^2");
  w.key("building_names").begin_array();
  for (std::size_t b = 0; b < t.buildings; ++b) w.value(names[b]);
  w.end_array();
  json_groups(w, t);
  if (!t.models.empty()) {
    w.key("models").begin_array();
    for (const auto& m : t.models) {
      w.begin_object().field("model", m.model).field("failed", m.failed_total);
      json_groups(w, m);
      w.end_object();
    }
    w.end_array();
  }
  w.end_object();
  std::cout << w.str() << "\n";
}

}  // namespace

int run_summary(int argc, const char* const* argv) {
  Options opt(
      "summary", "The amplification statistics of a campaign file (/amplification) as a table.",
      {{"input", "", "", "campaign result file (HDF5) of 'pound campaign' or 'pound merge'"},
       {"floors", "", "", "one row per floor instead of the largest median", true},
       {"json", "", "", "print one JSON object instead of the tables", true}});
  if (help_asked(opt, argc, argv)) return 0;
  if (!opt.given("input")) throw InputError("command line: --input RUN.h5 is required");
  const std::string input = opt.get_path("input");
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  if (H5Fis_hdf5(input.c_str()) <= 0)
    throw InputError(input +
                     ": cannot open as an HDF5 file; give a campaign result file written "
                     "by 'pound campaign --out'");
  const hid_t f = H5Fopen(input.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) throw InputError(input + ": cannot open for reading");
  struct Closer {
    hid_t f;
    ~Closer() { H5Fclose(f); }
  } closer{f};
  // A group written before issue 23 lacks the collapse shares and the per-model tables that the
  // file's datasets give: computed now, like a file without the group.
  AmplificationTable t;
  const bool stored = read_amplification(f, input, &t);
  const bool complete = stored && amplification_complete(f, t);
  if (!complete) t = compute_amplification(f, input);
  const std::string computed =
      complete ? ""
      : stored ? "computed now: the file's /amplification has no collapse shares or per-model "
                 "statistics (written by an older pound)"
               : "computed now: the file has no /amplification (written by an older pound)";
  const auto names =
      split_building_names(h5::root_attribute_text(f, "building_names"), t.buildings);
  if (opt.flag("json"))
    print_json(t, input, names, !complete);
  else
    print_text(t, names, h5::root_attribute_text(f, "intensity_measure"), opt.flag("floors"),
               computed);
  return 0;
}

}  // namespace pound::app
