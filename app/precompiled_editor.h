#pragma once
// What the editor's widget sources (interplay_app) nearly all include, compiled once for the target
// (app/CMakeLists.txt): the model's set and the widgets most panels use.

#include "precompiled_model.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QMouseEvent>
#include <QOpenGLWidget>
#include <QPainter>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QTableView>
#include <QToolButton>
#include <QVBoxLayout>
#include <QWidget>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "app/document/scene_document.h"
