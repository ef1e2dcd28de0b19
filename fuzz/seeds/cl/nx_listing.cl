Information listing created by	me
Date	x

TOOL PATH/A,TOOL,B
GOTO/1,0,1
Tool Path Listing has 2 lines.
