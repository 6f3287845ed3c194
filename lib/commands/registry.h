#pragma once
#include "commands/command.h"
