#include "io/pickle_reader.hpp"

#include <cstring>
#include <optional>
#include <unordered_map>

#include "io/input_error.hpp"
#include "src/std_compat.hpp"

namespace scantrace {

std::uint64_t PickledArray::size() const {
  std::uint64_t n = 1;
  for (const std::uint64_t d : shape) n *= d;
  return n;
}

std::string PickledArray::dtype() const {
  const char order = itemsize == 1 ? '|' : big_endian ? '>' : '<';
  return std::string(1, order) + kind + std::to_string(itemsize);
}

namespace {

// The byte offset of element i (C order) in an array of `shape` stored in Fortran order.
std::uint64_t fortran_offset(const std::vector<std::uint64_t>& shape, std::uint64_t i) {
  std::uint64_t offset = 0, stride = 1;
  std::vector<std::uint64_t> index(shape.size());
  for (std::size_t d = shape.size(); d-- > 0;) index[d] = i % shape[d], i /= shape[d];
  for (std::size_t d = 0; d < shape.size(); ++d) offset += index[d] * stride, stride *= shape[d];
  return offset;
}

// The element's bytes in little-endian order, widened to 8 (sign-extended for 'i').
std::uint64_t raw_element(const PickledArray& a, std::uint64_t i) {
  const std::uint64_t at = (a.fortran ? fortran_offset(a.shape, i) : i) * a.itemsize;
  unsigned char b[8] = {};
  for (int k = 0; k < a.itemsize; ++k)
    b[k] = static_cast<unsigned char>(a.data[at + (a.big_endian ? a.itemsize - 1 - k : k)]);
  if (a.kind == 'i' && a.itemsize < 8 && (b[a.itemsize - 1] & 0x80))
    for (int k = a.itemsize; k < 8; ++k) b[k] = 0xFF;
  std::uint64_t v = 0;
  for (int k = 7; k >= 0; --k) v = v << 8 | b[k];
  return v;
}

}  // namespace

double PickledArray::at(std::uint64_t i) const {
  const std::uint64_t v = raw_element(*this, i);
  if (kind == 'f') {
    if (itemsize == 4) return bit_cast<float>(static_cast<std::uint32_t>(v));
    if (itemsize == 8) return bit_cast<double>(v);
    return 0;  // float16 and longer floats are refused by the reader
  }
  if (kind == 'i') return static_cast<double>(static_cast<std::int64_t>(v));
  return static_cast<double>(v);
}

bool PickledArray::integer_at(std::uint64_t i, std::int64_t& out) const {
  const std::uint64_t v = raw_element(*this, i);
  if (kind == 'i') return out = static_cast<std::int64_t>(v), true;
  if (v > static_cast<std::uint64_t>(INT64_MAX)) return false;
  return out = static_cast<std::int64_t>(v), true;
}

std::string PickledArray::integer_text(std::uint64_t i) const {
  const std::uint64_t v = raw_element(*this, i);
  return kind == 'i' ? std::to_string(static_cast<std::int64_t>(v)) : std::to_string(v);
}

namespace {

// How deep the data nests: the object array's state tuple holds a list, which holds the dict,
// which holds arrays, whose state tuples hold shape tuples. Twice that is far beyond any real
// file; past it a pickle is refused, whatever the memory would allow.
constexpr int kMaxDepth = 12;
// The stack and the memo hold at most one entry per opcode; this bounds a pickle of MARKs alone.
constexpr std::size_t kMaxMarks = 64;

// The globals a numpy pickle names, and what each is here.
enum class Callable { none, reconstruct, ndarray, dtype, frombuffer, codecs_encode };

Callable allowed_global(const std::string& module, const std::string& name) {
  if ((module == "numpy.core.multiarray" || module == "numpy._core.multiarray") &&
      name == "_reconstruct")
    return Callable::reconstruct;
  if ((module == "numpy.core.numeric" || module == "numpy._core.numeric") && name == "_frombuffer")
    return Callable::frombuffer;
  if (module == "numpy" && name == "ndarray") return Callable::ndarray;
  if (module == "numpy" && name == "dtype") return Callable::dtype;
  if (module == "_codecs" && name == "encode") return Callable::codecs_encode;
  return Callable::none;
}

struct Value {
  enum class Kind { none, boolean, integer, text, bytes, tuple, list, dict, global, array, dtype };
  Kind kind = Kind::none;
  std::int64_t integer = 0;        // boolean, integer
  std::string text;                // text, bytes (raw), global ("module.name")
  std::vector<std::size_t> items;  // tuple, list; dict: key, value, key, value, …
  Callable callable = Callable::none;
  // array and dtype: the dtype (kind 'O' for object arrays); array: the rest once BUILD ran.
  PickledArray array;
  std::vector<std::size_t> objects;  // an object array's elements
  bool built = false;
  int depth = 0;
};

const char* kind_name(Value::Kind k) {
  switch (k) {
    case Value::Kind::none:
      return "None";
    case Value::Kind::boolean:
      return "a boolean";
    case Value::Kind::integer:
      return "an integer";
    case Value::Kind::text:
      return "a string";
    case Value::Kind::bytes:
      return "bytes";
    case Value::Kind::tuple:
      return "a tuple";
    case Value::Kind::list:
      return "a list";
    case Value::Kind::dict:
      return "a dict";
    case Value::Kind::global:
      return "a global";
    case Value::Kind::array:
      return "a numpy array";
    case Value::Kind::dtype:
      return "a numpy dtype";
  }
  return "a value";
}

class Machine {
 public:
  Machine(std::string_view bytes, const std::string& name) : b_(bytes), name_(name) {}

  std::size_t run() {
    for (;;) {
      op_at_ = i_;
      if (i_ >= b_.size()) fail("the pickle ends without its STOP opcode (truncated)");
      const auto op = static_cast<unsigned char>(b_[i_++]);
      if (op == '.') break;
      step(op);
    }
    if (stack_.size() != 1 || !marks_.empty())
      fail("STOP with " + std::to_string(stack_.size()) + " values on the stack (expected one)");
    return stack_.back();
  }

  const Value& value(std::size_t v) const { return values_[v]; }

  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(name_, "pickle byte " + std::to_string(op_at_), problem);
  }

 private:
  // One opcode, by family; an opcode no numpy pickle uses is refused.
  void step(unsigned char op) {
    if (framing(op) || scalar(op) || text_or_bytes(op) || container(op) || memo(op) || call(op))
      return;
    char hex[8];
    std::snprintf(hex, sizeof hex, "0x%02x", op);
    fail(std::string("opcode ") + hex + " ('" + (op >= 32 && op < 127 ? std::string(1, op) : "") +
         "') is not one a pickle of numpy arrays uses; refused");
  }

  // PROTO, FRAME, READONLY_BUFFER, MARK: nothing pushed but a mark.
  bool framing(unsigned char op) {
    switch (op) {
      case 0x80:  // PROTO
        read(1);
        return true;
      case 0x95:  // FRAME: its length only groups opcodes
        read(8);
        return true;
      case 0x98:  // READONLY_BUFFER: the value stays as it is
        return true;
      case '(':  // MARK
        mark();
        return true;
      default:
        return false;
    }
  }

  // None, booleans and integers.
  bool scalar(unsigned char op) {
    switch (op) {
      case 'N':
        push_new(Value::Kind::none);
        return true;
      case 0x88:  // NEWTRUE
        push_integer(1, Value::Kind::boolean);
        return true;
      case 0x89:  // NEWFALSE
        push_integer(0, Value::Kind::boolean);
        return true;
      case 'K':  // BININT1
        push_integer(unsigned_le(read(1)));
        return true;
      case 'M':  // BININT2
        push_integer(unsigned_le(read(2)));
        return true;
      case 'J':  // BININT
        push_integer(static_cast<std::int32_t>(unsigned_le(read(4))));
        return true;
      case 0x8a:  // LONG1
        long1();
        return true;
      default:
        return false;
    }
  }

  // Text and bytes, each with its length before it in 1, 4 or 8 bytes.
  bool text_or_bytes(unsigned char op) {
    struct Form {
      unsigned char op;
      Value::Kind kind;
      int length_bytes;
    };
    static constexpr Form kForms[] = {
        {'X', Value::Kind::text, 4},    // BINUNICODE
        {0x8c, Value::Kind::text, 1},   // SHORT_BINUNICODE
        {0x8d, Value::Kind::text, 8},   // BINUNICODE8
        {'C', Value::Kind::bytes, 1},   // SHORT_BINBYTES
        {'B', Value::Kind::bytes, 4},   // BINBYTES
        {0x8e, Value::Kind::bytes, 8},  // BINBYTES8
        {0x96, Value::Kind::bytes, 8},  // BYTEARRAY8
    };
    for (const Form& f : kForms)
      if (f.op == op) {
        push_string(f.kind, unsigned_le(read(static_cast<std::uint64_t>(f.length_bytes))));
        return true;
      }
    return false;
  }

  // Tuples, lists and dicts: made empty or from the stack, and filled.
  bool container(unsigned char op) {
    switch (op) {
      case ')':  // EMPTY_TUPLE
        push_container(Value::Kind::tuple, {});
        return true;
      case 0x85:  // TUPLE1
        push_container(Value::Kind::tuple, pop_n(1));
        return true;
      case 0x86:  // TUPLE2
        push_container(Value::Kind::tuple, pop_n(2));
        return true;
      case 0x87:  // TUPLE3
        push_container(Value::Kind::tuple, pop_n(3));
        return true;
      case 't':  // TUPLE
        push_container(Value::Kind::tuple, pop_mark());
        return true;
      case ']':  // EMPTY_LIST
        push_container(Value::Kind::list, {});
        return true;
      case '}':  // EMPTY_DICT
        push_container(Value::Kind::dict, {});
        return true;
      case 'a':  // APPEND
        add_items(Value::Kind::list, pop_n(1));
        return true;
      case 'e':  // APPENDS
        add_items(Value::Kind::list, pop_mark());
        return true;
      case 's':  // SETITEM
        add_items(Value::Kind::dict, pop_n(2));
        return true;
      case 'u':  // SETITEMS
        add_items(Value::Kind::dict, pop_mark());
        return true;
      default:
        return false;
    }
  }

  // The memo: values put aside by index and fetched again.
  bool memo(unsigned char op) {
    switch (op) {
      case 'q':  // BINPUT
        memo_put(unsigned_le(read(1)));
        return true;
      case 'r':  // LONG_BINPUT
        memo_put(unsigned_le(read(4)));
        return true;
      case 0x94:  // MEMOIZE
        memo_put(memo_.size());
        return true;
      case 'h':  // BINGET
        memo_get(unsigned_le(read(1)));
        return true;
      case 'j':  // LONG_BINGET
        memo_get(unsigned_le(read(4)));
        return true;
      default:
        return false;
    }
  }

  // Globals (only numpy's few, allowed_global) and what calls them.
  bool call(unsigned char op) {
    switch (op) {
      case 'c': {  // GLOBAL: module and name, one line each (in this order: not as arguments)
        const std::string module = line();
        global(module, line());
        return true;
      }
      case 0x93:  // STACK_GLOBAL
        stack_global();
        return true;
      case 'R':  // REDUCE
        reduce();
        return true;
      case 'b':  // BUILD
        build();
        return true;
      default:
        return false;
    }
  }

  // --- reading the byte stream ---
  std::string_view read(std::uint64_t n) {
    if (n > b_.size() - i_)
      fail("declares " + std::to_string(n) + " bytes, but only " + std::to_string(b_.size() - i_) +
           " are left in the file");
    const std::string_view s = b_.substr(i_, n);
    i_ += n;
    return s;
  }
  static std::uint64_t unsigned_le(std::string_view s) {
    std::uint64_t v = 0;
    for (std::size_t k = s.size(); k-- > 0;) v = v << 8 | static_cast<unsigned char>(s[k]);
    return v;
  }
  std::string line() {
    const std::size_t end = b_.find('\n', i_);
    if (end == std::string_view::npos || end - i_ > 200) fail("a GLOBAL name is not terminated");
    std::string s(b_.substr(i_, end - i_));
    i_ = end + 1;
    return s;
  }

  // --- the stack ---
  std::size_t add(Value v) {
    values_.push_back(std::move(v));
    return values_.size() - 1;
  }
  void push(std::size_t v) { stack_.push_back(v); }
  void push_new(Value::Kind k) {
    Value v;
    v.kind = k;
    push(add(std::move(v)));
  }
  void push_integer(std::int64_t i, Value::Kind k = Value::Kind::integer) {
    Value v;
    v.kind = k;
    v.integer = i;
    push(add(std::move(v)));
  }
  void long1() {
    const std::string_view s = read(unsigned_le(read(1)));
    if (s.size() > 8) fail("an integer of " + std::to_string(s.size()) + " bytes is too large");
    std::uint64_t v = unsigned_le(s);
    if (!s.empty() && s.size() < 8 && (static_cast<unsigned char>(s.back()) & 0x80))
      v |= ~std::uint64_t{0} << (8 * s.size());  // two's complement, sign-extended
    push_integer(static_cast<std::int64_t>(v));
  }
  void push_string(Value::Kind k, std::uint64_t n) {
    Value v;
    v.kind = k;
    v.text = std::string(read(n));
    push(add(std::move(v)));
  }
  void mark() {
    if (marks_.size() >= kMaxMarks) fail("more than 64 open MARKs: nested too deeply");
    marks_.push_back(stack_.size());
  }
  std::vector<std::size_t> pop_n(std::size_t n) {
    const std::size_t floor = marks_.empty() ? 0 : marks_.back();
    if (stack_.size() - floor < n) fail("the stack holds fewer values than the opcode takes");
    std::vector<std::size_t> out(stack_.end() - static_cast<std::ptrdiff_t>(n), stack_.end());
    stack_.resize(stack_.size() - n);
    return out;
  }
  std::vector<std::size_t> pop_mark() {
    if (marks_.empty()) fail("an opcode needs a MARK, and there is none");
    std::vector<std::size_t> out(stack_.begin() + static_cast<std::ptrdiff_t>(marks_.back()),
                                 stack_.end());
    stack_.resize(marks_.back());
    marks_.pop_back();
    return out;
  }
  std::size_t pop() { return pop_n(1)[0]; }
  std::size_t top() {
    if (stack_.empty() || (!marks_.empty() && marks_.back() == stack_.size()))
      fail("the stack is empty");
    return stack_.back();
  }

  int depth_of(const std::vector<std::size_t>& items) const {
    int d = 0;
    for (const std::size_t v : items) d = std::max(d, values_[v].depth);
    return d + 1;
  }
  void check_depth(int depth) const {
    if (depth > kMaxDepth)
      fail("containers nest deeper than " + std::to_string(kMaxDepth) +
           " levels (a dict of numpy arrays needs 5)");
  }
  void push_container(Value::Kind k, std::vector<std::size_t> items) {
    Value v;
    v.kind = k;
    v.depth = depth_of(items);
    check_depth(v.depth);
    v.items = std::move(items);
    push(add(std::move(v)));
  }
  void add_items(Value::Kind k, std::vector<std::size_t> items) {
    const std::size_t target = top();
    if (values_[target].kind != k)
      fail(std::string("adds items to ") + kind_name(values_[target].kind) + ", not to " +
           kind_name(k));
    if (k == Value::Kind::dict && items.size() % 2) fail("SETITEMS with a key but no value");
    const int depth = std::max(values_[target].depth, depth_of(items));
    check_depth(depth);
    values_[target].depth = depth;
    values_[target].items.insert(values_[target].items.end(), items.begin(), items.end());
  }

  void memo_put(std::uint64_t key) {
    if (memo_.size() > b_.size()) fail("more memo entries than bytes");
    memo_[key] = top();
  }
  void memo_get(std::uint64_t key) {
    const auto it = memo_.find(key);
    if (it == memo_.end()) fail("memo entry " + std::to_string(key) + " was never stored");
    push(it->second);
  }

  // --- globals and the calls it allows ---
  void global(const std::string& module, const std::string& name) {
    const Callable c = allowed_global(module, name);
    if (c == Callable::none)
      fail("global '" + module + "." + name +
           "' is refused: a scene pickle may name only numpy's array and dtype reconstructors "
           "(the file may be malicious; nothing was run)");
    Value v;
    v.kind = Value::Kind::global;
    v.text = module + "." + name;
    v.callable = c;
    push(add(std::move(v)));
  }
  void stack_global() {
    const std::size_t name = pop(), module = pop();
    if (values_[module].kind != Value::Kind::text || values_[name].kind != Value::Kind::text)
      fail("STACK_GLOBAL of values that are not strings");
    global(values_[module].text, values_[name].text);
  }

  const Value& argument(const std::vector<std::size_t>& args, std::size_t k, Value::Kind kind,
                        const char* what) const {
    if (k >= args.size() || values_[args[k]].kind != kind)
      fail(std::string(what) + " is not " + kind_name(kind));
    return values_[args[k]];
  }

  void reduce() {
    const std::size_t args = pop(), callable = pop();
    const Value& f = values_[callable];
    if (f.kind != Value::Kind::global) fail(std::string("REDUCE calls ") + kind_name(f.kind));
    const Value& a = values_[args];
    if (a.kind != Value::Kind::tuple) fail("REDUCE's arguments are not a tuple");
    const std::vector<std::size_t> items = a.items;
    switch (f.callable) {
      case Callable::reconstruct: {
        const Value& cls = argument(items, 0, Value::Kind::global, "_reconstruct's class");
        if (cls.callable != Callable::ndarray)
          fail("_reconstruct of '" + cls.text + "' (only numpy.ndarray is read)");
        Value v;
        v.kind = Value::Kind::array;  // its dtype, shape and data come with BUILD
        push(add(std::move(v)));
        return;
      }
      case Callable::dtype:
        push(add(dtype(argument(items, 0, Value::Kind::text, "dtype's name").text)));
        return;
      case Callable::frombuffer:
        push(add(frombuffer(items)));
        return;
      case Callable::codecs_encode:
        push(add(latin1(items)));
        return;
      case Callable::ndarray:
        fail("numpy.ndarray is called directly (only _reconstruct may use it)");
      case Callable::none:
        break;
    }
    fail("REDUCE of an unknown callable");
  }

  // np.dtype('f8'), as numpy's dtype.__reduce__ writes it (byte order set by BUILD).
  Value dtype(const std::string& name) const {
    Value v;
    v.kind = Value::Kind::dtype;
    if (name.size() < 2 || name.size() > 3) fail("dtype '" + name + "' is not read");
    const char kind = name[0];
    const int size = std::atoi(name.c_str() + 1);
    const bool number =
        (kind == 'f' && (size == 4 || size == 8)) ||
        ((kind == 'i' || kind == 'u') && (size == 1 || size == 2 || size == 4 || size == 8)) ||
        (kind == 'b' && size == 1) || (kind == 'O' && size == 8);
    if (!number)
      fail("dtype '" + name + "' is not read (float32/64, integers, bool and object only)");
    v.array.kind = kind;
    v.array.itemsize = size;
    return v;  // built: its byte order comes with BUILD (an array may use it before)
  }

  // numpy.core.numeric._frombuffer(buffer, dtype, shape, order): protocol 5's arrays.
  Value frombuffer(const std::vector<std::size_t>& args) {
    const Value& buffer = argument(args, 0, Value::Kind::bytes, "_frombuffer's buffer");
    const Value& dt = argument(args, 1, Value::Kind::dtype, "_frombuffer's dtype");
    const Value& shape = argument(args, 2, Value::Kind::tuple, "_frombuffer's shape");
    const Value& order = argument(args, 3, Value::Kind::text, "_frombuffer's order");
    Value v;
    v.kind = Value::Kind::array;
    v.array = dt.array;
    v.array.fortran = order.text == "F";
    set_shape(v.array, shape);
    set_data(v, buffer);
    v.built = true;
    return v;
  }

  // _codecs.encode(text, 'latin1'): how protocol 2 writes bytes.
  Value latin1(const std::vector<std::size_t>& args) const {
    const Value& text = argument(args, 0, Value::Kind::text, "encode's text");
    const Value& codec = argument(args, 1, Value::Kind::text, "encode's codec");
    if (codec.text != "latin1" && codec.text != "latin-1")
      fail("_codecs.encode with codec '" + codec.text + "' (only latin1 is read)");
    Value v;
    v.kind = Value::Kind::bytes;
    const std::string& s = text.text;
    for (std::size_t k = 0; k < s.size(); ++k) {  // UTF-8 of code points below 256
      const auto c = static_cast<unsigned char>(s[k]);
      if (c < 0x80) {
        v.text += static_cast<char>(c);
      } else if ((c == 0xC2 || c == 0xC3) && k + 1 < s.size()) {
        v.text +=
            static_cast<char>(((c & 0x03) << 6) | (static_cast<unsigned char>(s[++k]) & 0x3F));
      } else {
        fail("_codecs.encode of text that is not latin1");
      }
    }
    return v;
  }

  void build() {
    const std::size_t state = pop();
    const std::size_t target = top();
    if (values_[target].built)
      fail(std::string("BUILD of ") + kind_name(values_[target].kind) + " that is complete");
    if (values_[target].kind == Value::Kind::dtype)
      return build_dtype(values_[target], values_[state]);
    if (values_[target].kind != Value::Kind::array)
      fail(std::string("BUILD of ") + kind_name(values_[target].kind));
    const Value& s = values_[state];
    if (s.kind != Value::Kind::tuple || s.items.size() != 5)
      fail("an array's state is not (version, shape, dtype, fortran, data)");
    const std::vector<std::size_t> items = s.items;
    const Value& dt = argument(items, 2, Value::Kind::dtype, "the array's dtype");
    Value& a = values_[target];
    a.array = dt.array;
    set_shape(a.array, argument(items, 1, Value::Kind::tuple, "the array's shape"));
    a.array.fortran = argument(items, 3, Value::Kind::boolean, "the array's order").integer != 0;
    if (a.array.kind == 'O') {
      const Value& list = argument(items, 4, Value::Kind::list, "an object array's data");
      if (list.items.size() != a.array.size())
        fail("an object array of " + std::to_string(a.array.size()) + " elements holds " +
             std::to_string(list.items.size()));
      a.objects = list.items;
    } else {
      set_data(a, argument(items, 4, Value::Kind::bytes, "the array's data"));
    }
    a.built = true;
  }

  // dtype's state: (version, byte order, subarray, names, fields, elsize, alignment, flags[, …]).
  void build_dtype(Value& dt, const Value& state) const {
    if (state.kind != Value::Kind::tuple || state.items.size() < 8)
      fail("a dtype's state is not numpy's tuple");
    const Value& order = argument(state.items, 1, Value::Kind::text, "the dtype's byte order");
    for (std::size_t k = 2; k <= 4; ++k)
      if (values_[state.items[k]].kind != Value::Kind::none)
        fail("a structured or sub-array dtype (only plain numbers are read)");
    if (order.text == ">")
      dt.array.big_endian = true;
    else if (order.text != "<" && order.text != "|" && order.text != "=")
      fail("byte order '" + order.text + "' is not read");
    dt.built = true;
  }

  void set_shape(PickledArray& a, const Value& shape) const {
    if (shape.items.size() > 8) fail("an array of more than 8 dimensions");
    a.shape.clear();
    for (const std::size_t d : shape.items) {
      const Value& v = values_[d];
      if (v.kind != Value::Kind::integer || v.integer < 0 || v.integer > (std::int64_t{1} << 40))
        fail("an array dimension is not an integer in 0 .. 2^40");
      a.shape.push_back(static_cast<std::uint64_t>(v.integer));
    }
    std::uint64_t n = 1;
    for (const std::uint64_t d : a.shape)
      if (d != 0 && n > b_.size() / d)
        fail("an array's shape declares more elements than the file has bytes");
      else
        n *= d;
  }

  void set_data(Value& a, const Value& bytes) const {
    const std::uint64_t need = a.array.size() * static_cast<std::uint64_t>(a.array.itemsize);
    if (bytes.text.size() != need)
      fail("an array of shape " + shape_text(a.array.shape) + " and dtype " + a.array.dtype() +
           " needs " + std::to_string(need) + " bytes, its data holds " +
           std::to_string(bytes.text.size()));
    a.array.data = bytes.text;
  }

 public:
  static std::string shape_text(const std::vector<std::uint64_t>& shape) {
    std::string s = "(";
    for (std::size_t k = 0; k < shape.size(); ++k) s += (k ? ", " : "") + std::to_string(shape[k]);
    return s + (shape.size() == 1 ? ",)" : ")");
  }

 private:
  std::string_view b_;
  const std::string& name_;
  std::size_t i_ = 0, op_at_ = 0;
  std::vector<Value> values_;
  std::vector<std::size_t> stack_, marks_;
  std::unordered_map<std::uint64_t, std::size_t> memo_;
};

}  // namespace

std::map<std::string, PickledArray> read_pickled_arrays(std::string_view pickle,
                                                        const std::string& name) {
  Machine m(pickle, name);
  std::size_t top = m.run();
  const auto fail = [&](const std::string& problem) -> void {
    throw InputError(name, "pickle", problem);
  };
  // np.save of a dict: a 0-d object array whose one element is the dict.
  if (m.value(top).kind == Value::Kind::array) {
    const Value& a = m.value(top);
    if (a.array.kind != 'O' || a.objects.size() != 1)
      fail("holds one numpy array, not a dict of arrays (np.save(path, dict) writes that)");
    top = a.objects[0];
  }
  const Value& d = m.value(top);
  if (d.kind != Value::Kind::dict)
    fail(std::string("holds ") + kind_name(d.kind) + ", not a dict of numpy arrays");
  std::map<std::string, PickledArray> out;
  for (std::size_t k = 0; k + 1 < d.items.size(); k += 2) {
    const Value& key = m.value(d.items[k]);
    const Value& v = m.value(d.items[k + 1]);
    if (key.kind != Value::Kind::text) fail(std::string("a dict key is ") + kind_name(key.kind));
    if (v.kind != Value::Kind::array || !v.built || v.array.kind == 'O')
      fail("'" + key.text + "' is " +
           (v.kind == Value::Kind::array ? "an object array" : kind_name(v.kind)) +
           ", not a numeric numpy array");
    out[key.text] = v.array;
  }
  return out;
}

}  // namespace scantrace
