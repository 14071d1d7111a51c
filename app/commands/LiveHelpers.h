#pragma once

// What generate --publish and live share: the broker connection from the command line.
#include "HeadlessCommands.h"

#include "live/MqttClient.h"
#include "live/TopicMapping.h"

namespace drytwin::app::detail {

/// @brief The connection of --broker/--publish URL, --user, --password-file (else the environment's
/// DRYTWIN_MQTT_PASSWORD) and --cafile; an error names the option and the cause.
Expected<live::MqttConnectOptions> connectionOptions(const CommandOptions& o, const std::string& urlOption,
                                                     const std::string& clientRole);
/// @brief The topic mapping of --topics (or the defaults), with --topic-prefix applied.
Expected<live::TopicMapping> topicMapping(const CommandOptions& o);
/// @brief generate --publish: runs the plant and publishes its batches; the contract's exit code.
int publishPlant(const CommandOptions& o, const plant::PlantOptions& plant);

} // namespace drytwin::app::detail
