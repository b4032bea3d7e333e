#pragma once
// `stepwise record` and `stepwise replay`: a run to a file, and the file back to the same run.
//
//   stepwise record SCENE --frames N --output run.json [--chapter C]
//   stepwise replay run.json [--report out.json]
//
// replay exits 0 when every frame's state hash and the report match the recording, 1 when they
// part (naming the first frame that differs), 2 on a malformed recording (naming the JSON path).

#include "app/command.h"

namespace stepwise {

void installRecordCommand(Command program, int& exitCode);
void installReplayCommand(Command program, int& exitCode);

}  // namespace stepwise
