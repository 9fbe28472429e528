// The target colour picker (TargetColourPicker.py): Qt's colour dialog, opened on the selected
// models' current mixing_target_color; OK writes the chosen colour into their Per Model Settings.
import QtQuick 2.10
import QtQuick.Dialogs 1.3

ColorDialog {
    id: dialog
    title: "MixEngine: target colour of the selected models"
    showAlphaChannel: false
    color: manager.colour
    onAccepted: manager.accept(dialog.color.toString())
}
