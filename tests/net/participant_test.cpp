// Construction errors of the DDS layer surface as DdsError, never as asserts or crashes.
#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "net/dds_error.h"
#include "net/topic.h"
#include "net/writer.h"
#include "net_fixture.h"

namespace pool::net {
namespace {

using namespace protocol;

using namespace test;

class Construction : public NetTest {};

TEST_F(Construction, DomainOutOfRangeThrows) {
  EXPECT_THROW(Participant(kMaxDomainId + 1), DdsError);
}

TEST_F(Construction, AnInvalidTopicNameThrowsWithTheName) {
  Participant p(kConstruction);
  for (const char* name : {"", "bad name", "pool/x*", "a-b", "pool::x", "1abc"}) {
    try {
      Topic<pool_MatchInfo> bad(p, name);
      ADD_FAILURE() << "accepted topic name '" << name << "'";
    } catch (const DdsError& e) {
      EXPECT_LT(e.code(), 0);
      EXPECT_EQ(std::string(e.what()), "topic " + std::string(name) + ": Bad Parameter");
    }
  }
}

TEST_F(Construction, TwoTypesMayShareATopicNameInCyclone) {
  // Cyclone 0.10 (XTypes) allows it and matches only assignable types: names stay in topics.h.
  Participant p(kConstruction);
  Topic<pool_MatchState> state(p);
  EXPECT_NO_THROW(Topic<pool_MatchInfo>(p, topics::kMatchState));
}

TEST_F(Construction, EntitiesOutlivingTheirParticipantAreHarmless) {
  std::optional<Participant> p(std::in_place, kConstruction);
  Topic<pool_MatchInfo> topic(*p);
  Writer<pool_MatchInfo> writer(*p, topic, qos::lobby());
  p.reset();  // deletes the topic and writer inside DDS; their owners go later
  pool_MatchInfo info{};
  EXPECT_FALSE(writer.write(info));
}

}  // namespace
}  // namespace pool::net
