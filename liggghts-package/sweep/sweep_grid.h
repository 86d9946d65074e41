// hsrod-sweep: the case grid of a parameter sweep (no LIGGGHTS, no MPI).
// A swept variable takes values from a specification: comma-separated items,
// each a single value ("15e3"), an arithmetic range "start:stop:step" or a
// geometric range "start:stop:*factor", both inclusive of stop. The grid is
// the Cartesian product, the last --var varying fastest; case IDs number it
// from 0, so every rank derives the same case from the same ID.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace hsrod::sweep {

struct SweptVariable {
  std::string name;                 // LIGGGHTS variable name
  std::vector<std::string> values;  // as passed to -var (text, exactly as listed or formatted %.12g)
};

// Thrown for a malformed --var specification; the message names the
// variable, the item and the accepted forms.
struct GridError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Parses one --var specification into its values (see above).
std::vector<std::string> parse_values(const std::string &name, const std::string &spec);

class CaseGrid {
 public:
  explicit CaseGrid(std::vector<SweptVariable> variables);
  std::size_t size() const { return size_; }
  const std::vector<SweptVariable> &variables() const { return variables_; }
  // The value of every swept variable in case `id` (0 <= id < size()).
  std::vector<std::string> values_of(std::size_t id) const;

 private:
  std::vector<SweptVariable> variables_;
  std::size_t size_ = 1;
};

}  // namespace hsrod::sweep
