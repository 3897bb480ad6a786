// The renderer's logging category, "lightrig.render" (defined in renderer.cpp).
#pragma once

#include <QLoggingCategory>

Q_DECLARE_LOGGING_CATEGORY(lcRender)
