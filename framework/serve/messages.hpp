// The messages the page of `lab serve` sends over its WebSocket
// (docs/contract.md, `lab serve`): set, checkpoint, drag, scroll, key,
// reload, size, play and format.
#pragma once

#include <atomic>
#include <cstdint>
#include <nlohmann/json.hpp>

#include "framework/serve/live.hpp"

namespace fw {

// What a message may change of the connection that sent it.
struct ClientFlags {
    std::atomic<bool> png{false};      // frames as PNG (exact pixels) instead of JPEG
    std::atomic<bool> playing{false};  // it asked the lab to play
};

// Applies one message `m` to `live`; returns the version its change will show
// in. Throws fw::UsageError naming what is wrong with the message.
std::uint64_t apply_message(LiveLab& live, ClientFlags& client, const nlohmann::json& m);

}  // namespace fw
