#include "report_answer.h"

#include <algorithm>
#include <cstdio>

namespace medusa::cli {
namespace {

// Frame times and join times as whole MCS (frames are tens or hundreds of MCS apart).
std::string at_mcs(double t) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "MCS %.0f", t);
  return buffer;
}

std::string clusters(std::size_t n) { return n == 1 ? "one cluster" : std::to_string(n) + " clusters"; }

std::string joins_text(const std::vector<double>& joins) {
  if (joins.empty())
    return "no cluster ever joined another";
  if (joins.size() == 1)
    return "1 join, at " + at_mcs(joins.front());
  // The median join: half of them happened by then.
  return std::to_string(joins.size()) + " joins, half by " + at_mcs(joins[(joins.size() - 1) / 2]) +
         ", all by " + at_mcs(joins.back());
}

} // namespace

TypeCourse type_course(const std::vector<std::int64_t>& times, const std::vector<std::size_t>& b0,
                       const std::vector<double>& joins, std::size_t joined_at_first) {
  TypeCourse course;
  const std::size_t n = b0.size();
  if (n == 0 || times.size() != n)
    return course;
  course.first_clusters = b0.front();
  course.last_clusters = b0.back();
  const double t0 = static_cast<double>(times.front()), t_end = static_cast<double>(times.back());
  // The last stretch of frames at which the type is one cluster.
  std::size_t from = n;
  while (from > 0 && b0[from - 1] == 1)
    --from;
  std::string text = clusters(b0.front()) + " at " + at_mcs(t0);
  if (from == 0) {
    course.one_from_start = true;
    text = "one cluster at every frame, from " + at_mcs(t0) + " to the end (" + at_mcs(t_end) + ")";
  } else if (from < n) {
    if (b0.front() > 1)
      course.gathered_at = static_cast<double>(times[from]);
    else // one cluster at the first frame, split at some frames after it
      text += ", up to " + std::to_string(*std::max_element(b0.begin(), b0.end())) + " clusters later";
    text += from + 1 == n ? ", one cluster at the last frame (" + at_mcs(t_end) + ")"
                          : ", one cluster from " + at_mcs(static_cast<double>(times[from])) +
                                " to the end (" + at_mcs(t_end) + ")";
  } else {
    std::size_t first_one = n;
    for (std::size_t k = 1; k < n && first_one == n; ++k)
      if (b0[k] == 1)
        first_one = k;
    text += ", " + std::to_string(b0.back()) + " at " + at_mcs(t_end);
    if (b0.front() == 1)
      text += " (split after the first frame)";
    else if (first_one == n)
      text += ", never one cluster after " + at_mcs(t0);
    else
      text +=
          ", one cluster at " + at_mcs(static_cast<double>(times[first_one])) + " but split again by the end";
  }
  // Pieces that split off after the first frame and touch again were one cluster before: no join.
  const bool split_later = *std::max_element(b0.begin(), b0.end()) > b0.front();
  course.text = text + " (" +
                (joins.empty() && split_later ? "no join: the pieces that split off later were part of one "
                                                "cluster before"
                                              : joins_text(joins)) +
                (joined_at_first == 0 ? std::string()
                                      : "; " + std::to_string(joined_at_first) + " of the clusters at " +
                                            at_mcs(t0) + (joined_at_first == 1 ? " was" : " were") +
                                            " already joined to another through cells present at that "
                                            "frame only") +
                ")";
  return course;
}

std::string clusters_apart_text(const ClustersApart& c, std::size_t named) {
  if (c.cells == 0 || c.largest == c.cells)
    return "";
  std::string text =
      "the largest holds " + std::to_string(c.largest) + " of its " + std::to_string(c.cells) + " cells";
  if (c.tied || c.apart.empty() || c.apart.size() > named)
    return text;
  text += c.apart.size() == 1 ? "; cell " : "; cells ";
  for (std::size_t i = 0; i < c.apart.size(); ++i)
    text += (i == 0 ? "" : i + 1 == c.apart.size() ? " and " : ", ") + std::to_string(c.apart[i]);
  if (c.apart.size() == 1)
    return text + " is outside it";
  text += " are outside it, ";
  if (c.others == c.apart.size())
    return text + "each alone";
  return text +
         (c.others == 1 ? "in one other cluster" : "in " + std::to_string(c.others) + " other clusters");
}

std::string run_verdict(const std::vector<TypeVerdictInput>& types, const std::string& radius) {
  std::string gathered, at_start;
  std::size_t started_one = 0;
  for (const TypeVerdictInput& t : types) {
    if (t.course.gathered_at)
      gathered += (gathered.empty() ? "" : "; ") + t.title + " gathers into one cluster by " +
                  at_mcs(*t.course.gathered_at) + " and stays one to the end";
    if (t.course.one_from_start) {
      ++started_one;
      at_start += (at_start.empty() ? "" : ", ") + t.title;
    }
  }
  if (!gathered.empty())
    return "sorts at radius " + radius + ": " + gathered;
  if (!types.empty() && started_one == types.size())
    return "cannot tell at radius " + radius + ": every type is one cluster from the first frame on (" +
           at_start + "); the radius is too large to show sorting, see the radii below";
  std::string how_far;
  for (const TypeVerdictInput& t : types) {
    const TypeCourse& c = t.course;
    how_far += (how_far.empty() ? "" : "; ") + t.title;
    if (c.one_from_start)
      how_far += " is one cluster throughout";
    else if (c.first_clusters == c.last_clusters)
      how_far += " has " + clusters(c.first_clusters) + " at the first and at the last frame";
    else
      how_far += " goes from " + clusters(c.first_clusters) + " to " +
                 (c.last_clusters == 1 ? "one" : std::to_string(c.last_clusters));
    if (!t.apart.empty() && !c.one_from_start)
      how_far += " (" + t.apart + ")";
    if (!t.contacts.empty())
      how_far += ", " + t.contacts;
  }
  return "has no type in one cluster to the end at radius " + radius +
         (how_far.empty() ? "" : ": " + how_far);
}

} // namespace medusa::cli
