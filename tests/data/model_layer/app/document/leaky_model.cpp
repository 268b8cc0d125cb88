// A model source as tests/check_model_layer.cmake must refuse it (ctest model_layer_refuses_widgets):
// it includes an app header above the model, a widgets header and a widgets module path. The Gui
// header is allowed. Never compiled.
#include "app/viewport/viewport.h"

#include <QMessageBox>
#include <QUndoStack>
#include <QtWidgets/QWidget>
