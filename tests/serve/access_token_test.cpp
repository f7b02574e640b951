#include <gtest/gtest.h>

#include "app/serve/access_token.h"

namespace candela {
namespace {

TEST(AccessToken, NoTokenAdmitsEveryRequest) {
  EXPECT_TRUE(AccessToken().admits("/", ""));
  EXPECT_FALSE(AccessToken().required());
}

TEST(AccessToken, AdmitsTheTokenInTheQueryOrTheCookieOnly) {
  const AccessToken token("s3cret");
  EXPECT_TRUE(token.admits("/?token=s3cret", ""));
  EXPECT_TRUE(token.admits("/ws?x=1&token=s3cret", ""));
  EXPECT_TRUE(token.admits("/app.js", "theme=dark; candela_token=s3cret"));
  EXPECT_FALSE(token.admits("/", ""));
  EXPECT_FALSE(token.admits("/?token=", ""));
  EXPECT_FALSE(token.admits("/?token=s3cre", ""));
  EXPECT_FALSE(token.admits("/?token=s3cretx", ""));
  EXPECT_FALSE(token.admits("/?xtoken=s3cret", ""));
  EXPECT_FALSE(token.admits("/s3cret", "candela_token=wrong"));
  EXPECT_FALSE(token.admits("/", "other_token=s3cret"));
}

TEST(AccessToken, RandomTokensAre32HexDigitsAndDiffer) {
  const AccessToken a = AccessToken::random(), b = AccessToken::random();
  EXPECT_EQ(a.value().size(), 32u);
  EXPECT_EQ(a.value().find_first_not_of("0123456789abcdef"), std::string::npos);
  EXPECT_NE(a.value(), b.value());
}

TEST(AccessToken, LoopbackAddresses) {
  EXPECT_TRUE(isLoopbackAddress("127.0.0.1"));
  EXPECT_TRUE(isLoopbackAddress("127.1.2.3"));
  EXPECT_TRUE(isLoopbackAddress("::1"));
  EXPECT_TRUE(isLoopbackAddress("localhost"));
  EXPECT_FALSE(isLoopbackAddress("0.0.0.0"));
  EXPECT_FALSE(isLoopbackAddress("::"));
  EXPECT_FALSE(isLoopbackAddress("192.168.1.2"));
  EXPECT_FALSE(isLoopbackAddress("127.0.0.1.example.com"));
  EXPECT_FALSE(isLoopbackAddress("127.0.0"));
  EXPECT_FALSE(isLoopbackAddress("127.0.0.1234"));
  EXPECT_FALSE(isLoopbackAddress("127..0.1"));
}

TEST(AccessToken, SameOriginComparesTheOriginsHostWithTheRequestsHost) {
  EXPECT_TRUE(sameOrigin("", "127.0.0.1:8080"));
  EXPECT_TRUE(sameOrigin("http://127.0.0.1:8080", "127.0.0.1:8080"));
  EXPECT_TRUE(sameOrigin("https://gpu.example:8080", "gpu.example:8080"));
  EXPECT_FALSE(sameOrigin("http://evil.example", "127.0.0.1:8080"));
  EXPECT_FALSE(sameOrigin("http://127.0.0.1:8081", "127.0.0.1:8080"));
  EXPECT_FALSE(sameOrigin("null", "127.0.0.1:8080"));
}

TEST(AccessToken, LoopbackHosts) {
  for (const char* host : {"127.0.0.1:8080", "127.0.0.1", "localhost:80", "[::1]:8080", "[::1]"})
    EXPECT_TRUE(isLoopbackHost(host)) << host;
  for (const char* host : {"", "evil.example:8080", "localhost.evil.example", "127.0.0.1.evil.example:80", "[::1",
                           "[::2]:80", "10.0.0.1:8080"})
    EXPECT_FALSE(isLoopbackHost(host)) << host;
}

}  // namespace
}  // namespace candela
