// The Simulation settings panel. Hosted by a QQuickWidget in the editor's dock; the C++ side sets
// three context properties before loading it:
//   settingsModel  the scene's world settings (SimulationSettingsModel); every change is undoable
//   simulation     the running simulation (SimulationController): time scale
//   debugDraw      what the viewport overlays (DebugDrawOptions); a view preference, not an edit
// The settings' rows come from the model (one per schema setting), so a new setting needs nothing
// here. Controls write on user interaction only (onValueModified, onToggled, onActivated,
// onCommitted, onMoved, a label's drag), so updates from the model (undo, open) never echo back.
import QtQuick
import QtQuick.Controls.Fusion
import QtQuick.Layouts

Pane {
    id: root
    padding: 8

    // Units as people write them: m/s² rather than the files' and messages' m/s^2.
    function pretty(text) { return text.replace("^2", "²").replace("^3", "³") }

    // A scrubbed value `dx` pixels from where the drag started: integers one per 8 px, numbers by
    // half a percent of their size (or of a thousandth of their range, from zero) per pixel,
    // vectors scaled by e^(dx / 200). Values outside the setting's range are skipped, not sent.
    function scrub(field, start, dx) {
        let v
        if (field.type === "int") v = start + Math.round(dx / 8)
        else if (field.type === "vec3") v = start.map((c) => c * Math.exp(dx / 200))
        else v = start + dx * 0.005 * Math.max(Math.abs(start), 1e-3 * (field.maximum - field.minimum))
        const exclusive = field.range.startsWith("(")
        const inside = (x) => x <= field.maximum && (exclusive ? x > field.minimum : x >= field.minimum)
        if (field.type === "vec3" ? v.every(inside) : inside(v)) settingsModel.setValue(field.key, v)
    }

    // A number field: shows `value`, commits on Enter or focus loss. Text that is not a number is
    // handed to the model too, which rejects it with a message (and the field shows the old value).
    // Escape drops typed text and shows the value again.
    component NumberField: TextField {
        id: numberField
        property real value: 0
        readonly property string shown: Number(value).toLocaleString(Qt.locale("C"), "g", 6)
        signal committed(real number)
        text: shown
        horizontalAlignment: TextInput.AlignRight
        selectByMouse: true
        Layout.fillWidth: true
        Layout.preferredWidth: 60
        Keys.onEscapePressed: (event) => {
            event.accepted = text !== shown
            text = Qt.binding(() => shown)
        }
        onEditingFinished: {
            if (text.trim() !== shown) {  // tabbing through a field changes nothing
                const number = Number(text.trim())
                committed(text.trim() === "" ? NaN : number)
            }
            text = Qt.binding(() => shown)
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
                        // A click leaves the focus where it was, so Space still plays after a
                        // choice; Tab reaches it for the keyboard (then Space opens it).
                        focusPolicy: Qt.TabFocus
                        Layout.fillWidth: true
                        model: settingsModel.presetNames
                        currentIndex: settingsModel.preset
                        displayText: currentIndex < 0 ? qsTr("Custom") : currentText
                        onActivated: (index) => settingsModel.preset = index
                    }
                }
            }

            GroupBox {
                title: qsTr("Playback")
                Layout.fillWidth: true
                RowLayout {
                    anchors.fill: parent
                    Label { text: qsTr("Time scale") }
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

            // Every setting of simcore's schema, grouped as the model says: a row per setting with
            // its label and unit, an editor for its type, and its accepted range underneath.
            GroupBox {
                title: qsTr("World settings")
                Layout.fillWidth: true
                ColumnLayout {
                    anchors.fill: parent
                    spacing: 2
                    Repeater {
                        model: settingsModel
                        delegate: ColumnLayout {
                            id: field
                            required property string key
                            required property string group
                            required property bool firstInGroup
                            required property string label
                            required property string unit
                            required property string doc
                            required property string type
                            required property var minimum
                            required property var maximum
                            required property string range
                            required property var value
                            required property var choices
                            Layout.fillWidth: true
                            spacing: 0

                            Label {
                                visible: field.firstInGroup
                                text: field.group
                                font.bold: true
                                topPadding: 6
                                bottomPadding: 2
                            }
                            RowLayout {
                                Layout.fillWidth: true
                                Label {
                                    objectName: "label_" + field.key
                                    text: field.unit === "" ? field.label : field.label + " (" + root.pretty(field.unit) + ")"
                                    Layout.fillWidth: true
                                    elide: Text.ElideRight
                                    ToolTip.text: field.doc
                                    ToolTip.visible: hover.hovered && !scrub.active
                                    HoverHandler {
                                        id: hover
                                        cursorShape: scrub.enabled ? Qt.SizeHorCursor : Qt.ArrowCursor
                                    }
                                    // Dragging a number's label sideways scrubs it (a vector scales):
                                    // the model merges the whole drag into one history entry.
                                    DragHandler {
                                        id: scrub
                                        target: null
                                        enabled: field.type === "float" || field.type === "int" || field.type === "vec3"
                                        yAxis.enabled: false
                                        property var start
                                        onActiveChanged: {
                                            if (active) start = field.value
                                            settingsModel.interacting = active
                                        }
                                        onTranslationChanged: if (active) root.scrub(field, start, translation.x)
                                    }
                                }
                                Loader {
                                    Layout.preferredWidth: field.type === "vec3" ? 180 : field.type === "choice" ? 150 : 110
                                    sourceComponent: field.type === "bool" ? boolEditor
                                                   : field.type === "choice" ? choiceEditor
                                                   : field.type === "int" ? intEditor
                                                   : field.type === "vec3" ? vectorEditor : floatEditor
                                }
                            }
                            Label {
                                visible: field.range !== ""
                                text: root.pretty(field.range)
                                font.pointSize: Qt.application.font.pointSize * 0.85
                                opacity: 0.6
                                Layout.alignment: Qt.AlignRight
                            }

                            Component {
                                id: boolEditor
                                CheckBox {
                                    objectName: "setting_" + field.key
                                    checked: field.value
                                    onToggled: settingsModel.setValue(field.key, checked)
                                }
                            }
                            Component {
                                id: choiceEditor
                                ComboBox {
                                    objectName: "setting_" + field.key
                                    focusPolicy: Qt.TabFocus  // as the preset's
                                    model: field.choices
                                    currentIndex: field.value
                                    onActivated: (index) => settingsModel.setValue(field.key, index)
                                }
                            }
                            Component {
                                id: intEditor
                                SpinBox {
                                    id: spin
                                    objectName: "setting_" + field.key
                                    from: field.minimum; to: field.maximum
                                    editable: true
                                    value: field.value
                                    // Holding an arrow is one history entry: the model merges while interacting.
                                    readonly property bool held: up.pressed || down.pressed
                                    onHeldChanged: settingsModel.interacting = held
                                    onValueModified: settingsModel.setValue(field.key, value)
                                    Connections {  // a refused value goes back to the document's
                                        target: settingsModel
                                        function onChanged() { spin.value = field.value }
                                    }
                                }
                            }
                            Component {
                                id: floatEditor
                                NumberField {
                                    objectName: "setting_" + field.key
                                    value: field.value
                                    onCommitted: (number) => settingsModel.setValue(field.key, number)
                                }
                            }
                            Component {
                                id: vectorEditor
                                RowLayout {
                                    spacing: 2
                                    Repeater {
                                        model: 3
                                        NumberField {
                                            required property int index
                                            objectName: "setting_" + field.key + "." + index
                                            value: field.value[index]
                                            onCommitted: (number) => {
                                                const v = [field.value[0], field.value[1], field.value[2]]
                                                v[index] = number
                                                settingsModel.setValue(field.key, v)
                                            }
                                        }
                                    }
                                }
                            }
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
