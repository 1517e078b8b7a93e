# The library's stages in include order (README, Layout), one definition
# for test/t_layout.sh and scripts/walk.sh: each folder of src/lib
# includes only from itself and the stages before it; folders of one
# stage, written "a,b", would sit side by side.
LAYERS="base maps formats sample api"

# layer_rank FOLDER: its stage's place in LAYERS from 0, or 99.
layer_rank() {
	_r=0
	for _s in $LAYERS; do
		case ",$_s," in *",$1,"*) echo $_r; return ;; esac
		_r=$((_r + 1))
	done
	echo 99
}
