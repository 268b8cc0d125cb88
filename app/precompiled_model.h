#pragma once
// What the model layer's sources (interplay_model) nearly all include, compiled once for the target
// (app/CMakeLists.txt): it halves each source's compile. Qt Core and Gui only, like the model itself
// (tests/check_model_layer.cmake).

#include <QAbstractItemModel>
#include <QAbstractTableModel>
#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QList>
#include <QMimeData>
#include <QObject>
#include <QRegularExpression>
#include <QString>
#include <QStringList>
#include <QTimer>
#include <QUndoStack>

#include <algorithm>
#include <cmath>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "simcore/io/scene.h"
#include "simcore/world/world.h"
