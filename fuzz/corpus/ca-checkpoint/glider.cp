CAMLAB88-CA-CHECKPOINT 1
generation 0
edges wrap
seed 0
advance all
rules 37
|// The Game of Life, as printed in thesis figure 7.6 (comments as in the figure).
|
|1      1 1 1 1      //Life-form 1 sends messages at most
|                        //one cell above, one below, one to
|                        //the left and one to the right.
|
|COLOUR 00 FF 00 //A life-form of type 1 should appear green.
|                // The three hexadecimal numbers respectively
|                // define the intensity of the red, green and
|                // blue components of the colour - any colour
|                // which can be displayed, can be specified
|                // in this way.
|                //This item is optional - if it is omitted,
|                //each life-form has a unique representation.
|
|+1     +1   +1     //All eight immediate neighbours are sent the
|+1     |#X10 +1    //message to increment the number in their
|+1     +1   +1     //message area by one. The cell sends itself a
|                //message to OR the hexadecimal number 10
|                //(i.e. the binary number 10000) into its
|                //message area - #X indicates a hexadecimal
|                //number and #B is used for binary.
|
|$                               //This terminates the message passing rules.
|                               //The rules which follow define the actions to
|                               //be taken when message areas are inspected.
|
|#X12   1                   //if the number in the message area (after
|                               //all messages have been passed) is the
|                               //hexadecimal number 12 (the flag is set to
|                               //indicate that the cell was alive and the
|                               //"neighbour count" is 2) the new value in the
|                               //cell should be life-form 1
|
|#B?0011 1                 //if the message area contains 0...000011 or
|                               //0...010011 (? means either 0 or 1) the new
|                               //value at this position should be life-form 1
cells 5
21 20 1
22 21 1
20 22 1
21 22 1
22 22 1
end
