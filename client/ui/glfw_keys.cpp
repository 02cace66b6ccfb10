// GLFW key mapping.
#include "client/ui/glfw_keys.h"

#include <GLFW/glfw3.h>

namespace pool::ui {

std::optional<app::Key> keyOf(int glfw_key) {
  using app::Key;
  switch (glfw_key) {
    case GLFW_KEY_LEFT:
      return Key::Left;
    case GLFW_KEY_RIGHT:
      return Key::Right;
    case GLFW_KEY_UP:
      return Key::Up;
    case GLFW_KEY_DOWN:
      return Key::Down;
    case GLFW_KEY_SPACE:
      return Key::Space;
    case GLFW_KEY_A:
      return Key::A;
    case GLFW_KEY_Z:
      return Key::Z;
    case GLFW_KEY_S:
      return Key::S;
    case GLFW_KEY_X:
      return Key::X;
    case GLFW_KEY_G:
      return Key::G;
    case GLFW_KEY_V:
      return Key::V;
    case GLFW_KEY_C:
      return Key::C;
    case GLFW_KEY_K:
      return Key::K;
    case GLFW_KEY_P:
      return Key::P;
    case GLFW_KEY_T:
      return Key::T;
    case GLFW_KEY_L:
      return Key::L;
    case GLFW_KEY_B:
      return Key::B;
    case GLFW_KEY_O:
      return Key::O;
    case GLFW_KEY_F1:
      return Key::F1;
    case GLFW_KEY_R:
      return Key::R;
    case GLFW_KEY_N:
      return Key::N;
    case GLFW_KEY_F11:
      return Key::F11;
    case GLFW_KEY_Q:
      return Key::Q;
    case GLFW_KEY_Y:
      return Key::Y;
    case GLFW_KEY_I:
      return Key::I;
    case GLFW_KEY_ESCAPE:
      return Key::Escape;
    case GLFW_KEY_U:
      return Key::U;
    case GLFW_KEY_J:
      return Key::J;
    case GLFW_KEY_H:
      return Key::H;
    case GLFW_KEY_8:
      return Key::Num8;
    case GLFW_KEY_9:
      return Key::Num9;
    case GLFW_KEY_0:
      return Key::Num0;
    case GLFW_KEY_1:
      return Key::Num1;
    case GLFW_KEY_2:
      return Key::Num2;
    case GLFW_KEY_3:
      return Key::Num3;
    case GLFW_KEY_4:
      return Key::Num4;
    case GLFW_KEY_BACKSPACE:
      return Key::Backspace;
    case GLFW_KEY_F5:
      return Key::F5;
    case GLFW_KEY_F6:
      return Key::F6;
    case GLFW_KEY_F7:
      return Key::F7;
    case GLFW_KEY_TAB:
      return Key::Tab;
    case GLFW_KEY_MINUS:
    case GLFW_KEY_KP_SUBTRACT:
      return Key::Minus;
    case GLFW_KEY_EQUAL:
    case GLFW_KEY_KP_ADD:
      return Key::Equal;
    case GLFW_KEY_ENTER:
    case GLFW_KEY_KP_ENTER:
      return Key::Enter;
    default:
      return std::nullopt;
  }
}

app::Mods modsOf(int glfw_mods) {
  return {(glfw_mods & GLFW_MOD_SHIFT) != 0, (glfw_mods & GLFW_MOD_CONTROL) != 0,
          (glfw_mods & GLFW_MOD_ALT) != 0};
}

}  // namespace pool::ui
