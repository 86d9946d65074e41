#include "sweep_csv.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace hsrod::sweep {
namespace {

std::runtime_error file_error(const std::string &path, const std::string &what) {
  return std::runtime_error("result file '" + path + "': " + what);
}

void write_all(int fd, const std::string &text, const std::string &path) {
  // One write() of the whole line: O_APPEND places it at the end in one piece.
  const ssize_t written = ::write(fd, text.data(), text.size());
  if (written != static_cast<ssize_t>(text.size()))
    throw file_error(path, std::string("write failed: ") + std::strerror(errno));
}

void sync_file(int fd, const std::string &path) {
  if (::fsync(fd) != 0) throw file_error(path, std::string("fsync failed: ") + std::strerror(errno));
}

}  // namespace

std::string csv_field(const std::string &text) {
  std::string field = text;
  for (char &c : field)
    if (c == '\n' || c == '\r') c = ' ';
  if (field.find_first_of(",\"") == std::string::npos) return field;
  std::string quoted = "\"";
  for (char c : field) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

std::string csv_header(const CaseGrid &grid, const std::vector<std::string> &measure_names) {
  std::string header = "case";
  for (const SweptVariable &v : grid.variables()) header += "," + v.name;
  header += ",status";
  for (const std::string &m : measure_names) header += "," + csv_field(m);
  return header + ",error,wall_s,cpu_s,rank\n";
}

std::string csv_row(const CaseGrid &grid, std::size_t id, const CaseOutcome &outcome) {
  std::string row = std::to_string(id);
  for (const std::string &value : grid.values_of(id)) row += "," + value;
  row += outcome.ok ? ",ok" : ",failed";
  for (const std::string &m : outcome.measures) row += "," + csv_field(m);
  char times[64];
  std::snprintf(times, sizeof times, "%.4g,%.4g", outcome.wall_seconds, outcome.cpu_seconds);
  return row + "," + csv_field(outcome.error) + "," + times + "," + std::to_string(outcome.rank) + "\n";
}

ResultFile::ResultFile(const std::string &path, const CaseGrid &grid, const std::vector<std::string> &measure_names)
    : path_(path) {
  const std::string header = csv_header(grid, measure_names);
  std::string content;
  {
    std::ifstream in(path, std::ios::binary);
    if (in) {
      std::ostringstream all;
      all << in.rdbuf();
      content = all.str();
    }
  }
  // A kill during the write of a row can leave a torn last line: drop it.
  const std::size_t last_newline = content.rfind('\n');
  const std::size_t complete = last_newline == std::string::npos ? 0 : last_newline + 1;
  if (complete < content.size()) {
    if (::truncate(path.c_str(), static_cast<off_t>(complete)) != 0)
      throw file_error(path, std::string("cannot drop a torn last line: ") + std::strerror(errno));
    content.resize(complete);
  }
  fd_ = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CREAT, 0644);
  if (fd_ < 0) throw file_error(path, std::string("cannot open: ") + std::strerror(errno));
  if (content.empty()) {
    write_all(fd_, header, path);
    sync_file(fd_, path);
    return;
  }
  if (content.compare(0, header.size(), header) != 0)
    throw file_error(path, "its header differs from this sweep's (other variables or measures); "
                           "use --fresh to start a new sweep or another --output");
  std::istringstream rows(content.substr(header.size()));
  std::string row;
  std::size_t line = 1;
  while (std::getline(rows, row)) {
    ++line;
    const std::string where = "line " + std::to_string(line) + ": ";
    std::istringstream fields(row);
    std::string field;
    std::getline(fields, field, ',');
    std::size_t used = 0;
    unsigned long id = 0;
    try {
      id = std::stoul(field, &used);
    } catch (const std::exception &) {
      used = 0;
    }
    if (used == 0 || used != field.size() || id >= grid.size())
      throw file_error(path, where + "case ID '" + field + "' is not a case of this sweep (0.." +
                                 std::to_string(grid.size() - 1) + ")");
    for (const std::string &value : grid.values_of(id)) {
      std::getline(fields, field, ',');
      if (field != value)
        throw file_error(path, where + "case " + std::to_string(id) + " has value '" + field + "' where this sweep has '" +
                                   value + "' (other --var lists?); use --fresh or another --output");
    }
    // The status column: a row that is neither ok nor failed (an edited or
    // foreign file) must not count as a finished case.
    std::getline(fields, field, ',');
    if (field != "ok" && field != "failed")
      throw file_error(path, where + "case " + std::to_string(id) + " has status '" + field +
                                 "' (expected ok or failed); use --fresh or another --output");
    if (!finished_.insert(id).second)
      throw file_error(path, where + "case " + std::to_string(id) + " appears twice");
  }
}

ResultFile::~ResultFile() {
  if (fd_ >= 0) {
    ::fsync(fd_);
    ::close(fd_);
  }
}

void ResultFile::append(const std::string &row) { write_all(fd_, row, path_); }

void ResultFile::sync() { sync_file(fd_, path_); }

}  // namespace hsrod::sweep
