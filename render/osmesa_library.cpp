// Opening OSMesa by its soname and finding each function the canvas calls.
#include "render/osmesa_library.h"

#include <dlfcn.h>

#include <stdexcept>
#include <string>

namespace plantsim::render {
namespace {

// Debian's libosmesa6 ships libOSMesa.so.8; the unversioned name is the -dev package's link.
constexpr const char* kOsMesaSonames[] = {"libOSMesa.so.8", "libOSMesa.so"};

void* open_osmesa() {
  std::string errors;
  for (const char* name : kOsMesaSonames) {
    if (void* handle = dlopen(name, RTLD_NOW | RTLD_LOCAL)) return handle;
    if (const char* e = dlerror()) errors += std::string("; ") + e;
  }
  throw std::runtime_error("OSMesa cannot be opened (Debian package libosmesa6)" + errors);
}

template <class Function>
void find_function(void* handle, Function& f, const char* name) {
  f = reinterpret_cast<Function>(dlsym(handle, name));
  if (!f) throw std::runtime_error(std::string("OSMesa has no function ") + name);
}

OsMesaLibrary load_osmesa() {
  void* handle = open_osmesa();  // kept open for the process's life
  OsMesaLibrary l{};
  find_function(handle, l.create_context_ext, "OSMesaCreateContextExt");
  find_function(handle, l.destroy_context, "OSMesaDestroyContext");
  find_function(handle, l.make_current, "OSMesaMakeCurrent");
  find_function(handle, l.get_current_context, "OSMesaGetCurrentContext");
  find_function(handle, l.blend_func, "glBlendFunc");
  find_function(handle, l.clear, "glClear");
  find_function(handle, l.clear_color, "glClearColor");
  find_function(handle, l.color_pointer, "glColorPointer");
  find_function(handle, l.disable, "glDisable");
  find_function(handle, l.disable_client_state, "glDisableClientState");
  find_function(handle, l.draw_arrays, "glDrawArrays");
  find_function(handle, l.enable, "glEnable");
  find_function(handle, l.enable_client_state, "glEnableClientState");
  find_function(handle, l.finish, "glFinish");
  find_function(handle, l.load_identity, "glLoadIdentity");
  find_function(handle, l.matrix_mode, "glMatrixMode");
  find_function(handle, l.ortho, "glOrtho");
  find_function(handle, l.scissor, "glScissor");
  find_function(handle, l.vertex_pointer, "glVertexPointer");
  find_function(handle, l.viewport, "glViewport");
  return l;
}

}  // namespace

const OsMesaLibrary& osmesa() {
  static const OsMesaLibrary library = load_osmesa();
  return library;
}

}  // namespace plantsim::render
