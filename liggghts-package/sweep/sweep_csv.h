// hsrod-sweep: the result file, one CSV row per finished case (POSIX, no MPI).
// Columns: case, the swept variables, status (ok / failed), the measures,
// error (LIGGGHTS' ERROR line or how the case died; empty if ok), wall_s
// and cpu_s (the case's wall and CPU time in its process, s), rank (the MPI
// rank that ran it). The last three differ between runs of the same sweep.
// Rows are in the order cases finished. Each row is appended with one
// write() of the whole line, by one process only, so a row is either
// complete in the file or absent: a killed process loses nothing it wrote
// (the kernel holds the data). fsync() (durability against a crash of the
// machine itself) is done by sync() in groups (hsrod-sweep: at most once a
// second and at the end), because one fsync per row bounds the scheduler
// at ~100 rows/s on a busy disk. A sweep that is killed and
// started again reads the file, drops a torn last line, checks the header
// and that every row's values belong to its case ID, and runs only the
// cases without a row: every case ends up exactly once.
#pragma once

#include "sweep_grid.h"

#include <set>
#include <string>
#include <vector>

namespace hsrod::sweep {

struct CaseOutcome {
  bool ok = false;
  std::vector<std::string> measures;  // one per --measure (empty strings if failed)
  std::string error;                  // why the case failed
  double wall_seconds = 0.0;  // s, from fork to the end of the case's process
  double cpu_seconds = 0.0;   // s, user + system CPU time of the case's process
  int rank = 0;
};

std::string csv_header(const CaseGrid &grid, const std::vector<std::string> &measure_names);
std::string csv_row(const CaseGrid &grid, std::size_t id, const CaseOutcome &outcome);
// A CSV field: quoted if it holds a comma or a quote; newlines become blanks.
std::string csv_field(const std::string &text);

// Opens (creating if needed) the result file for appending. If it already
// holds rows of this sweep, returns their case IDs. Throws std::runtime_error
// (naming the file and the reason) if the file belongs to another sweep.
class ResultFile {
 public:
  ResultFile(const std::string &path, const CaseGrid &grid, const std::vector<std::string> &measure_names);
  ~ResultFile();
  ResultFile(const ResultFile &) = delete;
  ResultFile &operator=(const ResultFile &) = delete;
  const std::set<std::size_t> &finished() const { return finished_; }
  // Appends one row (a full line) with one write().
  void append(const std::string &row);
  // Makes every appended row durable (fsync).
  void sync();

 private:
  std::string path_;
  int fd_ = -1;
  std::set<std::size_t> finished_;
};

}  // namespace hsrod::sweep
