#include "core/hdf5_handle.hpp"

#include <mutex>

namespace revsph::hdf5 {

namespace {

Handle string_type() {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "cannot create an HDF5 string type");
  H5Tset_size(type.id(), H5T_VARIABLE);
  H5Tset_cset(type.id(), H5T_CSET_UTF8);
  return type;
}

Handle open_attribute(hid_t object, const std::string& name) {
  return Handle(H5Aopen(object, name.c_str(), H5P_DEFAULT), H5Aclose,
                "missing attribute '" + name + "'");
}

void write_attribute(hid_t object, const std::string& name, hid_t type, hid_t space,
                     const void* data) {
  if (H5Aexists(object, name.c_str()) > 0) {
    H5Adelete(object, name.c_str());
  }
  Handle attribute(H5Acreate2(object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT),
                   H5Aclose, "cannot create attribute '" + name + "'");
  if (H5Awrite(attribute.id(), type, data) < 0) {
    throw Hdf5Error("cannot write attribute '" + name + "'");
  }
}

} // namespace

void silence_library_errors() {
  static std::once_flag once;
  std::call_once(once, [] {
    // No library clean-up at exit: every file is closed explicitly (Handle), and after a failed
    // write (a full disk) HDF5 keeps the file it could not flush open; its exit handler then
    // tried to flush it again and crashed (H5F__close_cb, exit 139 after the clean message).
    // Must come before any other HDF5 call.
    H5dont_atexit();
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  });
}

void Handle::close(const std::string& what) {
  if (id_ >= 0 && close_ != nullptr) {
    const herr_t status = close_(id_);
    id_ = H5I_INVALID_HID;
    if (status < 0) {
      throw Hdf5Error(what);
    }
  }
}

void write_string_attribute(hid_t object, const std::string& name, const std::string& value) {
  const Handle type = string_type();
  const Handle space(H5Screate(H5S_SCALAR), H5Sclose, "cannot create a dataspace");
  const char* text = value.c_str();
  write_attribute(object, name, type.id(), space.id(), &text);
}

void write_strings_attribute(hid_t object, const std::string& name,
                             const std::vector<std::string>& values) {
  const Handle type = string_type();
  if (values.empty()) {
    // HDF5 cannot write a zero-length simple dataspace; an empty list is a null dataspace.
    const Handle space(H5Screate(H5S_NULL), H5Sclose, "cannot create a dataspace");
    if (H5Aexists(object, name.c_str()) > 0) {
      H5Adelete(object, name.c_str());
    }
    const Handle attribute(
        H5Acreate2(object, name.c_str(), type.id(), space.id(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
        "cannot create attribute '" + name + "'");
    return;
  }
  const hsize_t size = values.size();
  const Handle space(H5Screate_simple(1, &size, nullptr), H5Sclose, "cannot create a dataspace");
  std::vector<const char*> texts;
  for (const std::string& value : values) {
    texts.push_back(value.c_str());
  }
  write_attribute(object, name, type.id(), space.id(), texts.data());
}

void write_int_attribute(hid_t object, const std::string& name, long long value) {
  const Handle space(H5Screate(H5S_SCALAR), H5Sclose, "cannot create a dataspace");
  write_attribute(object, name, H5T_NATIVE_LLONG, space.id(), &value);
}

void write_double_attribute(hid_t object, const std::string& name, double value) {
  const Handle space(H5Screate(H5S_SCALAR), H5Sclose, "cannot create a dataspace");
  write_attribute(object, name, H5T_NATIVE_DOUBLE, space.id(), &value);
}

bool has_attribute(hid_t object, const std::string& name) {
  return H5Aexists(object, name.c_str()) > 0;
}

std::string read_string_attribute(hid_t object, const std::string& name) {
  const Handle attribute = open_attribute(object, name);
  const Handle stored(H5Aget_type(attribute.id()), H5Tclose, "unreadable attribute '" + name + "'");
  if (H5Tget_class(stored.id()) != H5T_STRING || H5Tis_variable_str(stored.id()) <= 0) {
    throw Hdf5Error("attribute '" + name + "' is not a string");
  }
  const Handle type = string_type();
  char* text = nullptr;
  if (H5Aread(attribute.id(), type.id(), &text) < 0 || text == nullptr) {
    throw Hdf5Error("cannot read attribute '" + name + "'");
  }
  std::string value(text);
  H5free_memory(text);
  return value;
}

std::vector<std::string> read_strings_attribute(hid_t object, const std::string& name) {
  const Handle attribute = open_attribute(object, name);
  const Handle space(H5Aget_space(attribute.id()), H5Sclose, "unreadable attribute '" + name + "'");
  if (H5Sget_simple_extent_type(space.id()) == H5S_NULL) {
    return {};
  }
  const hssize_t count = H5Sget_simple_extent_npoints(space.id());
  if (count < 0 || H5Sget_simple_extent_ndims(space.id()) != 1) {
    throw Hdf5Error("attribute '" + name + "' is not a list of strings");
  }
  const Handle type = string_type();
  std::vector<char*> texts(static_cast<std::size_t>(count), nullptr);
  if (count > 0 && H5Aread(attribute.id(), type.id(), texts.data()) < 0) {
    throw Hdf5Error("cannot read attribute '" + name + "'");
  }
  std::vector<std::string> values;
  for (char* text : texts) {
    values.emplace_back(text == nullptr ? "" : text);
    H5free_memory(text);
  }
  return values;
}

long long read_int_attribute(hid_t object, const std::string& name) {
  const Handle attribute = open_attribute(object, name);
  long long value = 0;
  if (H5Aread(attribute.id(), H5T_NATIVE_LLONG, &value) < 0) {
    throw Hdf5Error("cannot read attribute '" + name + "' as an integer");
  }
  return value;
}

double read_double_attribute(hid_t object, const std::string& name) {
  const Handle attribute = open_attribute(object, name);
  double value = 0;
  if (H5Aread(attribute.id(), H5T_NATIVE_DOUBLE, &value) < 0) {
    throw Hdf5Error("cannot read attribute '" + name + "' as a number");
  }
  return value;
}

} // namespace revsph::hdf5
