#pragma once
#include <cstdint>
#include <string>

#include "app/interactive/interactive_options.h"

namespace candela {

struct ServeOptions {
  InteractiveOptions interactive;  // what candela view takes too
  std::string bind = "127.0.0.1";
  uint16_t port = 8080;    // 0: any free port (the printed address names it)
  std::string token;       // required of every request; a random one is made when empty, unless noToken
  bool noToken = false;    // --no-token: no token on a loopback address (any local user may then steer it)
  bool offerVideo = true;  // browsers may take the H.264 stream instead of JPEG stripes
};

}  // namespace candela
