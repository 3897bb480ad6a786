// All undo commands of the editor (one family per file, each a RigCommand: rigcommand.h). Usually pushed
// through Document's convenience methods; each has a static create() that validates first and returns nullptr
// with a reason when refused. ChangeLightValue changes values of lights (ChangeLightValues: several
// properties as one step).
#pragma once

#include "editor/addlights.h"
#include "editor/applylightmix.h"
#include "editor/changelightvalue.h"
#include "editor/changelightvalues.h"
#include "editor/changerigspace.h"
#include "editor/changerigvalue.h"
#include "editor/duplicatelights.h"
#include "editor/movelights.h"
#include "editor/removelights.h"
#include "editor/replacerig.h"
