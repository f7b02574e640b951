#include <gtest/gtest.h>

#include "app/serve/client_messages.h"

namespace candela {
namespace {

std::optional<ClientMessage> parse(const std::string& text) {
  std::string problem;
  std::optional<ClientMessage> m = parseClientMessage(text, problem);
  EXPECT_EQ(m.has_value(), problem.empty()) << text;
  return m;
}

TEST(ClientMessages, ParsesEachKind) {
  auto pointer = parse(R"({"type":"pointer","action":"down","button":"middle","x":10.5,"y":20})");
  ASSERT_TRUE(pointer);
  const auto& p = std::get<PointerMessage>(*pointer);
  EXPECT_EQ(p.action, PointerMessage::Action::Down);
  EXPECT_EQ(p.button, MouseButton::Middle);
  EXPECT_EQ(p.x, 10.5);
  EXPECT_EQ(std::get<WheelMessage>(*parse(R"({"type":"wheel","steps":-2})")).steps, -2.0);
  EXPECT_TRUE(std::get<KeysMessage>(*parse(R"({"type":"keys","forward":true})")).held.forward);
  const auto resize = std::get<ResizeMessage>(*parse(R"({"type":"resize","width":640,"height":480})"));
  EXPECT_EQ(resize.width, 640u);
  EXPECT_EQ(std::get<ActionMessage>(*parse(R"({"type":"action","name":"save_view"})")).kind,
            ActionMessage::Kind::SaveView);
  EXPECT_EQ(std::get<FrameAckMessage>(*parse(R"({"type":"frame_ack","frame":12})")).frame, 12u);
}

TEST(ClientMessages, ParsesSettings) {
  auto m = parse(R"({"type":"settings","max_depth":4,"exposure":-1.5,"tonemap":"reinhard","denoiser":"atrous",
                     "shading":"disney","overrides":{"roughness":0.25,"metallic":null},"bilateral":true})");
  ASSERT_TRUE(m);
  const auto& s = std::get<SettingsMessage>(*m);
  EXPECT_EQ(s.maxDepth, 4u);
  EXPECT_EQ(s.exposure, -1.5f);
  EXPECT_EQ(s.toneMapper, ToneMapper::Reinhard);
  EXPECT_EQ(s.denoiser, DenoiserChoice::Atrous);
  EXPECT_EQ(s.shading, ShadingModel::Disney);
  ASSERT_EQ(s.overrides.size(), 2u);
  EXPECT_EQ(s.overrides[0].first, "metallic");  // JSON objects come in name order
  EXPECT_FALSE(s.overrides[0].second);
  EXPECT_EQ(s.overrides[1].second, 0.25f);
  EXPECT_FALSE(s.samplesPerFrame);
}

// The command line's limits (interactive_options.h), and the animation's controls.
TEST(ClientMessages, ParsesTheDepthLimitAndTheAnimation) {
  auto m = parse(R"({"type":"settings","max_depth":1024,"samples_per_frame":1024,"playing":false,"animation":2,
                     "animation_time":1.25})");
  ASSERT_TRUE(m);
  const auto& s = std::get<SettingsMessage>(*m);
  EXPECT_EQ(s.maxDepth, 1024u);
  EXPECT_EQ(s.samplesPerFrame, 1024u);
  EXPECT_EQ(s.playing, false);
  EXPECT_EQ(s.animationClip, 2u);
  EXPECT_EQ(s.animationTime, 1.25f);
}

TEST(ClientMessages, DropsMalformedMessagesWithAReason) {
  for (const char* text : {"",
                           "not json",
                           "{}",
                           "[]",
                           "42",
                           "null",
                           R"({"type":7})",
                           R"({"type":"teleport"})",
                           R"({"type":"pointer"})",
                           R"({"type":"pointer","action":"down","x":"a","y":1})",
                           R"({"type":"pointer","action":"down","x":1e300,"y":1})",
                           R"({"type":"pointer","action":"fly","x":1,"y":1})",
                           R"({"type":"wheel"})",
                           R"({"type":"wheel","steps":1e9})",
                           R"({"type":"resize","width":0,"height":10})",
                           R"({"type":"resize","width":100000,"height":100})",
                           R"({"type":"resize","width":100.5,"height":100})",
                           R"({"type":"resize","width":100})",
                           R"({"type":"settings","max_depth":0})",
                           R"({"type":"settings","max_depth":1025})",
                           R"({"type":"settings","samples_per_frame":true})",
                           R"({"type":"settings","samples_per_frame":1025})",
                           R"({"type":"settings","playing":1})",
                           R"({"type":"settings","animation":-1})",
                           R"({"type":"settings","animation":0.5})",
                           R"({"type":"settings","animation_time":"later"})",
                           R"({"type":"settings","animation_time":1e300})",
                           R"({"type":"settings","exposure":"bright"})",
                           R"({"type":"settings","tonemap":"filmic"})",
                           R"({"type":"settings","overrides":{"roughness":2}})",
                           R"({"type":"settings","overrides":{"nonsense":0.5}})",
                           R"({"type":"settings","overrides":[0.5]})",
                           R"({"type":"keys","forward":1})",
                           R"({"type":"action"})",
                           R"({"type":"action","name":"delete"})",
                           R"({"type":"frame_ack","frame":-1})",
                           R"({"type":"frame_ack"})"}) {
    std::string problem;
    EXPECT_FALSE(parseClientMessage(text, problem)) << text;
    EXPECT_FALSE(problem.empty()) << text;
  }
}

TEST(ClientMessages, SurvivesDeepNesting) {
  std::string problem;
  EXPECT_FALSE(parseClientMessage(std::string(16 * 1024, '['), problem));
  std::string objects;
  for (int i = 0; i < 3000; ++i) objects += "{\"a\":";
  EXPECT_FALSE(parseClientMessage(objects, problem));
}

// Client text in a problem (an unknown type, a material parameter's name) is printed on the server's terminal:
// it comes out short and without escape sequences, line ends or bytes that are not UTF-8.
TEST(ClientMessages, QuotesClientTextShortAndPrintable) {
  // Escape, BEL, CSI, line ends and the C1 CSI (U+009B), as JSON escapes, then a long line.
  const std::string hostile = R"(\u001b]0;owned\u0007\u001b[31m\r\n\u009b)" + std::string(3000, 'A');
  const std::string messages[] = {R"({"type":")" + hostile + R"("})",
                                  R"({"type":"settings","overrides":{")" + hostile + R"(":0.5}})"};
  for (const std::string& message : messages) {
    std::string problem;
    EXPECT_FALSE(parseClientMessage(message, problem));
    EXPECT_LE(problem.size(), 4 * kMaxQuotedClientBytes + 80) << problem;
    for (char c : problem) {
      EXPECT_GE(static_cast<unsigned char>(c), 0x20) << problem;
      EXPECT_NE(c, '\x7f') << problem;
    }
    EXPECT_EQ(problem.find("\xc2\x9b"), std::string::npos) << "a C1 control (CSI) survived";
    EXPECT_NE(problem.find("..."), std::string::npos) << problem;
  }
}

}  // namespace
}  // namespace candela
