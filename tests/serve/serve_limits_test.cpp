// candela serve against clients that try to keep others out or the server up: connections that send half a
// request, requests without the token, and a SIGTERM while a long frame renders.
#include <gtest/gtest.h>

#include <signal.h>

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "app/serve/http_server.h"
#include "network_clients.h"
#include "serve_process.h"

namespace candela::test {
namespace {

const std::vector<std::string> kSmallServer = {"cornell-box", "--backend", "cpu",      "--port", "0",
                                               "--width",     "64",        "--height", "64"};

// More connections than every limit from one address, each holding half a request: the page still loads, at
// once, from another address and from the same one, and the server has closed all but a few of them.
TEST(ServeLimits, HalfOpenConnectionsFromOneAddressLockNobodyOut) {
  ServeProcess server(CANDELA_EXECUTABLE, kSmallServer, 120.0);
  const std::string page = "/?token=" + server.token();
  std::vector<std::unique_ptr<HalfOpenRequest>> held;
  for (int i = 0; i < kMaxHttpConnections + 36; ++i)
    held.push_back(std::make_unique<HalfOpenRequest>(server.port(), "127.0.0.1"));
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(httpGet(server.port(), page, "", "127.0.0.2").status, 200u) << "from another address";
  EXPECT_EQ(httpGet(server.port(), page, "", "127.0.0.1").status, 200u) << "from the same address";
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 2.0) << "the page waited for the held connections to time out";
  int open = 0;
  for (auto& connection : held) open += !connection->closedByServer(0.2);
  EXPECT_LE(open, kMaxHttpConnectionsPerAddress);
  EXPECT_EQ(server.stop(30.0), 0) << server.stderrText();
}

// The connections that are left time out: none holds its place longer than the header's deadline.
TEST(ServeLimits, AHalfSentRequestIsClosedAfterTheHeaderDeadline) {
  ServeProcess server(CANDELA_EXECUTABLE, kSmallServer, 120.0);
  HalfOpenRequest held(server.port(), "127.0.0.1");
  const double deadline = std::chrono::duration<double>(kHeaderTimeout).count();
  EXPECT_TRUE(held.closedByServer(deadline + 2.0));
  EXPECT_EQ(server.stop(30.0), 0) << server.stderrText();
}

// By default a token is needed on loopback too: a local user who has not seen the address gets nothing.
TEST(ServeLimits, AClientWithoutTheTokenIsRefusedByDefault) {
  ServeProcess server(CANDELA_EXECUTABLE, kSmallServer, 120.0);
  ASSERT_EQ(server.token().size(), 32u) << server.url();
  EXPECT_EQ(httpGet(server.port(), "/").status, 403u);
  EXPECT_EQ(httpGet(server.port(), "/app.js").status, 403u);
  EXPECT_EQ(httpGet(server.port(), "/?token=" + server.token().substr(1)).status, 403u);
  EXPECT_THROW(WebSocketClient(server.port(), ""), std::exception);
  EXPECT_EQ(httpGet(server.port(), "/?token=" + server.token()).status, 200u);
  EXPECT_NO_THROW(WebSocketClient(server.port(), server.token()));
  EXPECT_EQ(server.stop(30.0), 0) << server.stderrText();
}

TEST(ServeLimits, NoTokenServesLoopbackOnlyWhenAsked) {
  std::vector<std::string> arguments = kSmallServer;
  arguments.push_back("--no-token");
  ServeProcess server(CANDELA_EXECUTABLE, arguments, 120.0);
  EXPECT_TRUE(server.token().empty()) << server.url();
  EXPECT_EQ(httpGet(server.port(), "/").status, 200u);
  EXPECT_EQ(server.stop(30.0), 0) << server.stderrText();
}

// A frame that takes minutes (large, many samples, deep paths) is in flight when SIGTERM comes: the server ends
// within 2 seconds all the same.
TEST(ServeLimits, SigtermDuringALongFrameEndsTheServerWithinTwoSeconds) {
  ServeProcess server(CANDELA_EXECUTABLE,
                      {"cornell-box", "--backend", "cpu", "--port", "0", "--width", "2048", "--height", "2048",
                       "--spp-per-frame", "64", "--max-depth", "64"},
                      120.0);
  WebSocketClient browser(server.port(), server.token());
  browser.send(R"({"type":"resize","width":2048,"height":2048})");
  // The greeting comes just before the first frame is rendered.
  for (bool greeted = false; !greeted;) greeted = browser.read().text.find("\"hello\"") != std::string::npos;
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  const auto start = std::chrono::steady_clock::now();
  server.signal(SIGTERM);
  EXPECT_EQ(server.wait(10.0), 0);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 2.0);
  EXPECT_NE(server.stderrText().find("candela serve: stopped"), std::string::npos) << server.stderrText();
}

}  // namespace
}  // namespace candela::test
