#pragma once
// A restricted reader of Python pickles of numpy arrays: what the course's hw1.npy holds (np.save
// of a dict of four arrays, i.e. a pickled 0-d object array whose one element is the dict).
//
// It is not an unpickler. It interprets the opcodes that pickle protocols 2 to 5 use for a dict
// of strings to numpy arrays (about 40), on values of its own (None, booleans, integers, strings,
// bytes, tuples, lists, dicts, arrays, dtypes), and the only globals it accepts are the names of
// numpy's array and dtype reconstructors (and `_codecs.encode`, protocol 2's way to write bytes),
// each of which it carries out itself, building plain values. It never imports, calls or constructs
// anything else: any other global (`os.system`, `builtins.eval`, …) is refused by name at the byte
// it appears, before anything after it is read. Every declared size is checked against the bytes
// left in the file before it is allocated, and containers may not nest deeper than the data needs.
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace scantrace {

// A numpy array as the pickle describes it: shape, dtype and the raw bytes of its elements.
struct PickledArray {
  std::vector<std::uint64_t> shape;
  char kind = 0;  // numpy's dtype kind: 'f' float, 'i' signed, 'u' unsigned, 'b' bool
  int itemsize = 0;
  bool big_endian = false;
  bool fortran = false;
  std::string data;  // product(shape) × itemsize bytes, in the order `fortran` says

  std::uint64_t size() const;  // the number of elements
  std::string dtype() const;   // numpy's name: "<f4", ">i8", "|u1"
  // Element i (in C order) as a double: integers above 2^53 are rounded, as float64 would.
  double at(std::uint64_t i) const;
  // Element i of an integer array, exact; false when it does not fit an int64.
  bool integer_at(std::uint64_t i, std::int64_t& out) const;
  // Element i of an integer array as text, exact (for messages).
  std::string integer_text(std::uint64_t i) const;
};

// The dict of arrays `pickle` holds: directly, or as the one element of a 0-d object array (what
// np.save writes for a dict). `name` starts every error. Throws InputError(name, "pickle byte N",
// problem) for anything else.
std::map<std::string, PickledArray> read_pickled_arrays(std::string_view pickle,
                                                        const std::string& name);

}  // namespace scantrace
