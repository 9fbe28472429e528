// The channels of the filament mix, over Cura's Preview while the Material Color scheme shows the mix
// (MixPreview.py sets mixLegend: channels [{name, color}], shown, title).
import QtQuick 2.7

import UM 1.1 as UM

Rectangle
{
    id: legend
    objectName: "mixEngineLegend"
    visible: mixLegend.shown
    x: UM.Theme.getSize("default_margin").width * 2
    // below the Preview's stage menu (View type, Color scheme), above the disabled tool bar on the left
    y: UM.Theme.getSize("main_window_header").height + UM.Theme.getSize("stage_menu").height
       + UM.Theme.getSize("default_margin").height
    z: 10
    width: Math.max(title.implicitWidth, rows.implicitWidth) + 2 * padding
    height: column.implicitHeight + 2 * padding
    radius: UM.Theme.getSize("default_radius").width
    color: UM.Theme.getColor("main_background")
    border.width: UM.Theme.getSize("default_lining").width
    border.color: UM.Theme.getColor("lining")

    property int padding: UM.Theme.getSize("default_margin").width

    Column
    {
        id: column
        x: legend.padding
        y: legend.padding
        spacing: UM.Theme.getSize("narrow_margin").height

        Text
        {
            id: title
            text: mixLegend.title
            font: UM.Theme.getFont("default_bold")
            color: UM.Theme.getColor("text")
            renderType: Text.NativeRendering
        }

        Column
        {
            id: rows
            spacing: UM.Theme.getSize("narrow_margin").height

            Repeater
            {
                model: mixLegend.channels

                Row
                {
                    spacing: UM.Theme.getSize("narrow_margin").width

                    Rectangle
                    {
                        width: UM.Theme.getSize("layerview_legend_size").width
                        height: UM.Theme.getSize("layerview_legend_size").height
                        anchors.verticalCenter: parent.verticalCenter
                        color: modelData.color
                        border.width: UM.Theme.getSize("default_lining").width
                        border.color: UM.Theme.getColor("lining")
                    }

                    Text
                    {
                        text: "Channel " + modelData.name + "  " + modelData.color
                        font: UM.Theme.getFont("default")
                        color: UM.Theme.getColor("text")
                        renderType: Text.NativeRendering
                    }
                }
            }
        }
    }
}
