// The Simulation settings panel. Hosted by a QQuickWidget in the editor's dock; the C++ side sets
// three context properties before loading it:
//   settingsModel  the scene's world settings (SimulationSettingsModel); every change is undoable
//   simulation     the running simulation (SimulationController): time scale
//   debugDraw      what the viewport overlays (DebugDrawOptions); a view preference, not an edit
// Controls write on user interaction only (onValueModified, onToggled, onActivated, onMoved), so
// updates coming from the model (undo, open) never echo back as new edits.
import QtQuick
import QtQuick.Controls.Fusion
import QtQuick.Layouts

Pane {
    id: root
    padding: 8

    // A number field: shows `value`, commits on Enter or focus loss. Text that is not a number is
    // handed to the model too, which rejects it with a message (and the field shows the old value).
    component NumberField: TextField {
        property real value: 0
        signal committed(real number)
        text: Number(value).toLocaleString(Qt.locale("C"), "g", 6)
        horizontalAlignment: TextInput.AlignRight
        selectByMouse: true
        Layout.fillWidth: true
        Layout.preferredWidth: 60
        onEditingFinished: {
            const number = Number(text.trim())
            committed(text.trim() === "" ? NaN : number)
            text = Qt.binding(() => Number(value).toLocaleString(Qt.locale("C"), "g", 6))
        }
    }

    ScrollView {
        anchors.fill: parent
        contentWidth: availableWidth
        clip: true

        ColumnLayout {
            width: parent.width
            spacing: 10

            GroupBox {
                title: qsTr("Quality")
                Layout.fillWidth: true
                GridLayout {
                    anchors.fill: parent
                    columns: 2
                    Label { text: qsTr("Preset") }
                    ComboBox {
                        id: presetBox
                        objectName: "presetComboBox"
                        Layout.fillWidth: true
                        model: settingsModel.presetNames
                        currentIndex: settingsModel.preset
                        displayText: currentIndex < 0 ? qsTr("Custom") : currentText
                        onActivated: (index) => settingsModel.preset = index
                    }
                }
            }

            GroupBox {
                title: qsTr("Time")
                Layout.fillWidth: true
                GridLayout {
                    anchors.fill: parent
                    columns: 2
                    Label { text: qsTr("Steps per second") }
                    SpinBox {
                        objectName: "stepRateSpinBox"
                        Layout.fillWidth: true
                        from: 10; to: 2000; stepSize: 10
                        editable: true
                        value: Math.round(settingsModel.stepRate)
                        onValueModified: settingsModel.stepRate = value
                    }
                    Label { text: qsTr("Substeps") }
                    SpinBox {
                        objectName: "substepsSpinBox"
                        Layout.fillWidth: true
                        from: 1; to: 64
                        editable: true
                        value: settingsModel.substeps
                        onValueModified: settingsModel.substeps = value
                    }
                    Label { text: qsTr("Time scale") }
                    RowLayout {
                        Slider {
                            objectName: "timeScaleSlider"
                            Layout.fillWidth: true
                            from: 0.05; to: 2.0
                            value: simulation.timeScale
                            onMoved: simulation.timeScale = value
                        }
                        Label {
                            text: simulation.timeScale.toFixed(2) + "×"
                            Layout.preferredWidth: 40
                        }
                    }
                }
            }

            GroupBox {
                title: qsTr("Solver")
                Layout.fillWidth: true
                GridLayout {
                    anchors.fill: parent
                    columns: 2
                    Label { text: qsTr("Velocity iterations") }
                    SpinBox {
                        objectName: "velocityIterationsSpinBox"
                        Layout.fillWidth: true
                        from: 1; to: 1000
                        editable: true
                        value: settingsModel.velocityIterations
                        onValueModified: settingsModel.velocityIterations = value
                    }
                    Label { text: qsTr("Position iterations") }
                    SpinBox {
                        objectName: "positionIterationsSpinBox"
                        Layout.fillWidth: true
                        from: 0; to: 1000
                        editable: true
                        value: settingsModel.positionIterations
                        onValueModified: settingsModel.positionIterations = value
                    }
                    Label { text: qsTr("Position correction") }
                    ComboBox {
                        objectName: "positionCorrectionComboBox"
                        Layout.fillWidth: true
                        model: settingsModel.positionCorrectionNames
                        currentIndex: settingsModel.positionCorrection
                        onActivated: (index) => settingsModel.positionCorrection = index
                    }
                    Label { text: qsTr("Integrator") }
                    ComboBox {
                        objectName: "integratorComboBox"
                        Layout.fillWidth: true
                        model: settingsModel.integratorNames
                        currentIndex: settingsModel.integrator
                        onActivated: (index) => settingsModel.integrator = index
                    }
                }
            }

            GroupBox {
                title: qsTr("Gravity (m/s²)")
                Layout.fillWidth: true
                ColumnLayout {
                    anchors.fill: parent
                    RowLayout {
                        Label { text: "x" }
                        NumberField {
                            objectName: "gravityXField"
                            value: settingsModel.gravityX
                            onCommitted: (number) => settingsModel.setGravity(number, settingsModel.gravityY, settingsModel.gravityZ)
                        }
                        Label { text: "y" }
                        NumberField {
                            objectName: "gravityYField"
                            value: settingsModel.gravityY
                            onCommitted: (number) => settingsModel.setGravity(settingsModel.gravityX, number, settingsModel.gravityZ)
                        }
                        Label { text: "z" }
                        NumberField {
                            objectName: "gravityZField"
                            value: settingsModel.gravityZ
                            onCommitted: (number) => settingsModel.setGravity(settingsModel.gravityX, settingsModel.gravityY, number)
                        }
                    }
                    // Dragging the slider is one undo entry: the model merges while interacting.
                    Slider {
                        objectName: "gravityYSlider"
                        Layout.fillWidth: true
                        from: -20; to: 0
                        value: settingsModel.gravityY
                        onPressedChanged: settingsModel.interacting = pressed
                        onMoved: settingsModel.setGravity(settingsModel.gravityX, value, settingsModel.gravityZ)
                    }
                }
            }

            GroupBox {
                title: qsTr("Damping (1/s)")
                Layout.fillWidth: true
                GridLayout {
                    anchors.fill: parent
                    columns: 4
                    Label { text: qsTr("Linear") }
                    NumberField {
                        objectName: "linearDampingField"
                        value: settingsModel.linearDamping
                        onCommitted: (number) => settingsModel.linearDamping = number
                    }
                    Label { text: qsTr("Angular") }
                    NumberField {
                        objectName: "angularDampingField"
                        value: settingsModel.angularDamping
                        onCommitted: (number) => settingsModel.angularDamping = number
                    }
                }
            }

            GroupBox {
                title: qsTr("Effects")
                Layout.fillWidth: true
                GridLayout {
                    anchors.fill: parent
                    columns: 3
                    Repeater {
                        model: settingsModel.effectNames
                        CheckBox {
                            required property int index
                            required property string modelData
                            objectName: "effect_" + modelData
                            text: modelData
                            checked: settingsModel.effects[index]
                            onToggled: settingsModel.setEffect(index, checked)
                        }
                    }
                }
            }

            GroupBox {
                title: qsTr("Debug drawing")
                Layout.fillWidth: true
                GridLayout {
                    anchors.fill: parent
                    columns: 2
                    CheckBox {
                        objectName: "drawAabbsCheckBox"
                        text: qsTr("Bounding boxes")
                        checked: debugDraw.aabbs
                        onToggled: debugDraw.aabbs = checked
                    }
                    CheckBox {
                        objectName: "drawContactPointsCheckBox"
                        text: qsTr("Contact points")
                        checked: debugDraw.contactPoints
                        onToggled: debugDraw.contactPoints = checked
                    }
                    CheckBox {
                        objectName: "drawContactNormalsCheckBox"
                        text: qsTr("Contact normals")
                        checked: debugDraw.contactNormals
                        onToggled: debugDraw.contactNormals = checked
                    }
                    CheckBox {
                        objectName: "sleepingTintCheckBox"
                        text: qsTr("Tint sleeping bodies")
                        checked: debugDraw.sleepingTint
                        onToggled: debugDraw.sleepingTint = checked
                    }
                }
            }

            Item { Layout.fillHeight: true }
        }
    }
}
