#pragma once
// Owning wrappers of HDF5 C-API identifiers, and the string attributes snapshots use. HDF5's
// own error printing is switched off: every failure becomes one Hdf5Error with our message.

#include <hdf5.h>

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace revsph::hdf5 {

class Hdf5Error : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// Stops the HDF5 library from printing its error stack and from cleaning up at exit (once per
// process, before any other HDF5 call).
void silence_library_errors();

class Handle {
public:
  using Close = herr_t (*)(hid_t);
  Handle() = default;
  Handle(hid_t id, Close closer, const std::string& what) : id_(id), close_(closer) {
    if (id_ < 0) {
      throw Hdf5Error(what);
    }
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& other) noexcept
      : id_(std::exchange(other.id_, H5I_INVALID_HID)), close_(other.close_) {}
  Handle& operator=(Handle&& other) noexcept {
    reset();
    id_ = std::exchange(other.id_, H5I_INVALID_HID);
    close_ = other.close_;
    return *this;
  }
  ~Handle() { reset(); }

  hid_t id() const { return id_; }
  // Closes now, reporting failure (a file's final flush happens here).
  void close(const std::string& what);

private:
  void reset() {
    if (id_ >= 0 && close_ != nullptr) {
      close_(id_);
    }
    id_ = H5I_INVALID_HID;
  }
  hid_t id_ = H5I_INVALID_HID;
  Close close_ = nullptr;
};

void write_string_attribute(hid_t object, const std::string& name, const std::string& value);
void write_strings_attribute(hid_t object, const std::string& name,
                             const std::vector<std::string>& values);
void write_int_attribute(hid_t object, const std::string& name, long long value);
void write_double_attribute(hid_t object, const std::string& name, double value);

bool has_attribute(hid_t object, const std::string& name);
std::string read_string_attribute(hid_t object, const std::string& name);
std::vector<std::string> read_strings_attribute(hid_t object, const std::string& name);
long long read_int_attribute(hid_t object, const std::string& name);
double read_double_attribute(hid_t object, const std::string& name);

} // namespace revsph::hdf5
