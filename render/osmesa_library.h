// OSMesa and the GL functions the canvas calls, opened on first use (dlopen) rather than linked:
// OSMesa brings llvmpipe, LLVM, Z3 and ICU, which every process paid for at start-up (26 ms and
// 55 MiB for `plantsim --version`, issue 54) though most commands draw nothing.
#pragma once

#include <GL/gl.h>
#include <GL/osmesa.h>

namespace plantsim::render {

struct OsMesaLibrary {
  decltype(&::OSMesaCreateContextExt) create_context_ext;
  decltype(&::OSMesaDestroyContext) destroy_context;
  decltype(&::OSMesaMakeCurrent) make_current;
  decltype(&::OSMesaGetCurrentContext) get_current_context;
  decltype(&::glBlendFunc) blend_func;
  decltype(&::glClear) clear;
  decltype(&::glClearColor) clear_color;
  decltype(&::glColorPointer) color_pointer;
  decltype(&::glDisable) disable;
  decltype(&::glDisableClientState) disable_client_state;
  decltype(&::glDrawArrays) draw_arrays;
  decltype(&::glEnable) enable;
  decltype(&::glEnableClientState) enable_client_state;
  decltype(&::glFinish) finish;
  decltype(&::glLoadIdentity) load_identity;
  decltype(&::glMatrixMode) matrix_mode;
  decltype(&::glOrtho) ortho;
  decltype(&::glScissor) scissor;
  decltype(&::glVertexPointer) vertex_pointer;
  decltype(&::glViewport) viewport;
};

/// The library, opened and its functions found the first time it is asked for (thread-safe);
/// throws std::runtime_error naming the library and the missing function when it cannot.
const OsMesaLibrary& osmesa();

}  // namespace plantsim::render
